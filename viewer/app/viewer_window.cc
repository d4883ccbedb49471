#include "viewer_window.h"

#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <algorithm>
#include <cfloat>
#include <chrono>
#include <cstdio>
#include <iostream>

#include "draw_style.h"
#include "panels.h"
#include "scene_view.h"
#include "screenshot.h"

namespace vantage::viewer::app {
namespace {

void report_glfw_error(int code, const char* text) {
  std::cerr << "vantage-viewer: GLFW error " << code << ": " << text << "\n";
}

GLFWwindow* open_window(const WindowOptions& options, const std::string& title) {
  glfwSetErrorCallback(report_glfw_error);
  if (!glfwInit()) {
    std::cerr << "vantage-viewer: cannot start GLFW (no display? run under xvfb-run -a for "
                 "headless use)\n";
    return nullptr;
  }
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 0);
  GLFWwindow* window =
      glfwCreateWindow(options.width, options.height, title.c_str(), nullptr, nullptr);
  if (window == nullptr) {
    std::cerr << "vantage-viewer: cannot open an OpenGL 3.0 window\n";
    glfwTerminate();
    return nullptr;
  }
  glfwMakeContextCurrent(window);
  glfwSwapInterval(options.screenshot_path.empty() ? 1 : 0);
  return window;
}

// One frame: ImGui widgets for the session. Returns nothing; drawing data is ready afterwards.
void build_frame(ViewerSession& session, SceneView& scene, Panels& panels, bool interactive,
                 GLFWwindow* window) {
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  if (!interactive) ImGui::GetIO().MousePos = ImVec2(-FLT_MAX, -FLT_MAX);
  ImGui::NewFrame();
  int width = 0;
  int height = 0;
  glfwGetWindowSize(window, &width, &height);
  const Viewport viewport = scene_viewport(width, height);
  const float column = static_cast<float>(width - viewport.width);
  const std::optional<Eigen::Vector3d> hovered = scene.draw(session, viewport, interactive);
  panels.draw(session, hovered, width - column, column, static_cast<float>(height));
  if (interactive) panels.handle_keys(session);
  ImGui::Render();
}

// Dear ImGui on the window: context, fonts and style, GLFW and OpenGL back ends.
void start_imgui(GLFWwindow* window) {
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;
  setup_fonts_and_style();
  ImGui_ImplGlfw_InitForOpenGL(window, true);
  ImGui_ImplOpenGL3_Init("#version 130");
}

// Draws the frame built by ImGui into the framebuffer, whose size it returns, and waits for it.
void render(GLFWwindow* window, int* fb_width, int* fb_height) {
  glfwGetFramebufferSize(window, fb_width, fb_height);
  glViewport(0, 0, *fb_width, *fb_height);
  glClearColor(0.11f, 0.12f, 0.14f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  glFinish();  // so that each frame's time includes its own drawing
}

// Saves the framebuffer to --screenshot and prints what it shows; 0, or 1 if it cannot.
int save_screenshot(ViewerSession& session, const WindowOptions& options, int fb_width,
                    int fb_height, int frames_timed, double longest_frame_ms) {
  if (!save_framebuffer_png(options.screenshot_path, fb_width, fb_height)) {
    std::cerr << "vantage-viewer: " << options.screenshot_path << ": cannot write PNG\n";
    return 1;
  }
  const AnalysisSnapshot& snap = *session.analysis();
  std::printf(
      "vantage-viewer: wrote %s (%dx%d); analysis of %d data vectors took %.3f s "
      "on the worker thread; UI frames after the first: %d, longest %.1f ms\n",
      options.screenshot_path.c_str(), fb_width, fb_height,
      static_cast<int>(snap.data.vectors.cols()), snap.seconds, frames_timed, longest_frame_ms);
  return 0;
}

void close_window(GLFWwindow* window) {
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  glfwDestroyWindow(window);
  glfwTerminate();
}

}  // namespace

int run_window(ViewerSession& session, const WindowOptions& options) {
  const bool screenshot = !options.screenshot_path.empty();
  GLFWwindow* window = open_window(options, "vantage-viewer: " + session.layout().name);
  if (window == nullptr) return 1;
  start_imgui(window);

  SceneView scene;
  Panels panels;
  bool view_pending = !session.apply_view(options.view);
  int frames_ready = 0;
  int frame_count = 0;
  int frames_timed = 0;
  double longest_frame_ms = 0.0;  // UI frames after the first, analysis excluded
  int status = 0;
  const auto start = std::chrono::steady_clock::now();
  while (!glfwWindowShouldClose(window)) {
    if (screenshot) {
      glfwPollEvents();
    } else {
      glfwWaitEventsTimeout(1.0 / 30.0);  // wakes for input; polls the worker 30 times a second
    }
    const auto frame_start = std::chrono::steady_clock::now();
    session.poll();
    if (view_pending && session.analysis_current()) {
      session.apply_view(options.view);  // a failed analysis leaves the camera where it is
      view_pending = false;
    }
    build_frame(session, scene, panels, !screenshot, window);
    int fb_width = 0;
    int fb_height = 0;
    render(window, &fb_width, &fb_height);
    if (frame_count++ > 0) {  // the first frame builds the font atlas and shaders
      ++frames_timed;
      longest_frame_ms = std::max(
          longest_frame_ms,
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - frame_start)
              .count());
    }
    if (screenshot) {
      const bool ready = session.analysis_current() && !session.augmenting() &&
                         !session.placing() && !view_pending;
      if (ready && ++frames_ready >= options.frames) {
        status =
            save_screenshot(session, options, fb_width, fb_height, frames_timed, longest_frame_ms);
        break;
      }
      const double waited =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      if (!ready && waited > options.timeout_seconds) {
        std::cerr << "vantage-viewer: the analysis or placement did not finish within --timeout\n";
        status = 1;
        break;
      }
    }
    glfwSwapBuffers(window);
  }
  close_window(window);
  return status;
}

}  // namespace vantage::viewer::app
