// A user technique's shared constant block (renderer/techniques/user/user_pass.h): the AO block
// every technique starts with and nothing else; its own values come in SsaoUserParams
// (SSAO_UBO_USER, generated from the file's header). Shared by C++ and GLSL; both include
// bindings.h first (the shader loader inlines every #include line, so this file includes nothing).
#ifndef SSAOLAB_USER_LAYOUT_H
#define SSAOLAB_USER_LAYOUT_H
#ifndef SSAOLAB_BINDINGS_H
#error "include shaders/include/bindings.h before this file"
#endif
#ifdef __cplusplus
namespace ssao::gpu {
#endif

SSAO_STRUCT UserConstants_ {
    AoCommon_ aoCommon; // radius, power, target size, noise kind, normal source, optional inputs
};

#ifdef __cplusplus
using UserConstants = UserConstants_;
static_assert(sizeof(UserConstants) == sizeof(AoCommon), "std140 layout");
} // namespace ssao::gpu
#endif
#endif
