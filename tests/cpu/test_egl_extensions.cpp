// Which EGL client extension strings make HeadlessContext try the device platform (a real GPU).
#include "gl/context.h"

#include <gtest/gtest.h>

using ssao::gl::eglClientOffersDevices;

TEST(EglExtensions, DevicePlatformIsTriedWhereEnumerationComesEitherWay) {
    // NVIDIA 580.159 on an H200 (read there): enumeration only inside EGL_EXT_device_base.
    EXPECT_TRUE(eglClientOffersDevices(
        "EGL_EXT_platform_base EGL_EXT_device_base EGL_KHR_client_get_all_proc_addresses "
        "EGL_EXT_client_extensions EGL_KHR_debug EGL_KHR_platform_x11 EGL_EXT_platform_x11 "
        "EGL_EXT_platform_device EGL_MESA_platform_surfaceless EGL_EXT_explicit_device"));
    // Mesa 22 (Debian 12): the split extensions.
    EXPECT_TRUE(eglClientOffersDevices(
        "EGL_EXT_device_base EGL_EXT_device_enumeration EGL_EXT_device_query EGL_EXT_platform_base "
        "EGL_KHR_client_get_all_proc_addresses EGL_EXT_client_extensions EGL_KHR_debug "
        "EGL_EXT_platform_device EGL_EXT_platform_wayland EGL_MESA_platform_surfaceless"));
    // No device platform, or no way to enumerate devices: not tried.
    EXPECT_FALSE(eglClientOffersDevices("EGL_EXT_platform_base EGL_EXT_device_base EGL_MESA_platform_surfaceless"));
    EXPECT_FALSE(eglClientOffersDevices("EGL_EXT_platform_base EGL_EXT_platform_device EGL_EXT_device_query"));
    // Whole names only: a longer name holding the text is not the extension.
    EXPECT_FALSE(eglClientOffersDevices("EGL_EXT_platform_device EGL_EXT_device_base_v2"));
    EXPECT_FALSE(eglClientOffersDevices(""));
    EXPECT_FALSE(eglClientOffersDevices(nullptr));
}
