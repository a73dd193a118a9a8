#include "ui_driver.h"
#include "gl/readback.h"

#include "base/image.h"

#include <backends/imgui_impl_opengl3.h>
#include <gtest/gtest.h>

namespace ssaotest {

namespace {
constexpr int kEnterKey = 257; // any free index of io.KeysDown, mapped below
}

UiDriver::UiDriver(const ssao::AppOptions& o, int width, int height) : w_(width), h_(height) {
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    io.DisplaySize = ImVec2(float(w_), float(h_));
    io.KeyMap[ImGuiKey_Enter] = kEnterKey;
    ImGui_ImplOpenGL3_Init("#version 450 core");
    target_.ensure(w_, h_, GL_RGBA8, "test.ui");
    app_ = std::make_unique<ssao::AppCore>(o);
    frame();
}

UiDriver::~UiDriver() {
    app_.reset();
    ImGui_ImplOpenGL3_Shutdown();
    ImGui::DestroyContext();
}

void UiDriver::frame(float x, float y, bool down) {
    ImGuiIO& io = ImGui::GetIO();
    io.DeltaTime = 1.0f / 60.0f;
    io.MousePos = ImVec2(x, y);
    io.MouseDown[0] = down;
    mx_ = x, my_ = y;
    ImGui_ImplOpenGL3_NewFrame();
    ImGui::NewFrame();
    app_->drawUi();
    ImGui::Render();
    target_.bind();
    ssao::clearUiBackground(); // as the app does (window_app.cpp)
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void UiDriver::save(const std::string& path) const {
    ssao::writePng(ssao::readBack(target_.texture(), 3), path);
}

ImVec4 UiDriver::rect(const std::string& key) const {
    auto it = app_->view().widgetRects.find(key);
    EXPECT_NE(it, app_->view().widgetRects.end()) << "no widget recorded as " << key;
    return it == app_->view().widgetRects.end() ? ImVec4(0, 0, 0, 0) : it->second;
}

void UiDriver::clickAt(float x, float y, bool ctrl, bool shift) {
    ImGuiIO& io = ImGui::GetIO();
    io.KeyCtrl = ctrl;
    io.KeyShift = shift;
    frame(x, y, false);
    frame(x, y, true);
    io.KeyCtrl = false;
    io.KeyShift = false;
    frame(x, y, false);
}

void UiDriver::click(const std::string& key, float fx, bool ctrl) {
    const ImVec4 r = rect(key);
    clickAt(r.x + (r.z - r.x) * fx, (r.y + r.w) * 0.5f, ctrl);
}

void UiDriver::drag(float x0, float y0, float x1, float y1, int steps) {
    frame(x0, y0, false);
    frame(x0, y0, true);
    for (int i = 1; i <= steps; ++i)
        frame(x0 + (x1 - x0) * float(i) / float(steps), y0 + (y1 - y0) * float(i) / float(steps), true);
    frame(x1, y1, false);
}

void UiDriver::type(const std::string& text) {
    ImGuiIO& io = ImGui::GetIO();
    for (char c : text)
        io.AddInputCharacter(unsigned(c));
    frame(mx_, my_, false);
}

void UiDriver::wheel(float x, float y, float steps) {
    ImGuiIO& io = ImGui::GetIO();
    frame(x, y, false);
    io.MouseWheel = steps;
    frame(x, y, false);
    io.MouseWheel = 0;
    frame(x, y, false);
}

void UiDriver::settle() {
    for (int i = 0; i < 40 && (app_->frames().interacting() || app_->frames().renderedInteractive()); ++i)
        frame(mx_, my_, false);
    frame(mx_, my_, false);
}

void UiDriver::pressEnter() {
    ImGuiIO& io = ImGui::GetIO();
    io.KeysDown[kEnterKey] = true;
    frame(mx_, my_, false);
    io.KeysDown[kEnterKey] = false;
    frame(mx_, my_, false);
}

} // namespace ssaotest
