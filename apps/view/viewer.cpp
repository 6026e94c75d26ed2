#include "viewer.hpp"

#include <epoxy/gl.h>
// GLFW after the GL loader, and without its own GL header.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "camera.hpp"
#include "colour_map.hpp"
#include "fluid_feed.hpp"
#include "particle_renderer.hpp"
#include "png_writer.hpp"
#include "probe.hpp"
#include "sph/error.hpp"
#include "view_panel.hpp"
#include "viewer_state.hpp"

namespace sph::view {

namespace {

using Clock = std::chrono::steady_clock;

std::string glfwError() {
  const char* description = nullptr;
  glfwGetError(&description);
  return description ? description : "unknown error";
}

struct GlfwSession {
  GlfwSession() {
    if (!glfwInit())
      throw std::runtime_error("sph view: cannot open a window (" + glfwError() +
                               "); a display is needed: run it on a desktop, or under "
                               "xvfb-run for a screenshot; `sph render` needs none");
  }
  ~GlfwSession() { glfwTerminate(); }
  GlfwSession(const GlfwSession&) = delete;
  GlfwSession& operator=(const GlfwSession&) = delete;
};

// Destroyed after what draws in its context (declared before it).
struct Window {
  GLFWwindow* handle;
  Window(int width, int height, const std::string& title);
  ~Window() { glfwDestroyWindow(handle); }
  Window(const Window&) = delete;
  Window& operator=(const Window&) = delete;
};

Window::Window(int width, int height, const std::string& title) {
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_SAMPLES, 4);
  handle = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
  if (handle == nullptr)
    throw std::runtime_error("sph view: cannot open an OpenGL 3.3 core window: " + glfwError());
  glfwMakeContextCurrent(handle);
  glfwSwapInterval(1);
}

struct ImGuiSession {
  explicit ImGuiSession(GLFWwindow* window) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini left in the working directory
    ImGui::StyleColorsDark();
    ImGui_ImplGlfw_InitForOpenGL(window, true);
    ImGui_ImplOpenGL3_Init("#version 330 core");
  }
  ~ImGuiSession() {
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
  }
  ImGuiSession(const ImGuiSession&) = delete;
  ImGuiSession& operator=(const ImGuiSession&) = delete;
};

render::Box3f boxOf(const AxisBox& box) {
  return {{float(box.min[0]), float(box.min[1]), float(box.min[2])},
          {float(box.max[0]), float(box.max[1]), float(box.max[2])}};
}

render::Rgb rgbOf(const Vec3d& v) {
  return {float(v[0]), float(v[1]), float(v[2])};
}

// Keys act on their press, not while held.
void handleKeys(ViewerState& state) {
  if (ImGui::GetIO().WantCaptureKeyboard) return;
  render::DrawSettings& d = state.draw;
  if (ImGui::IsKeyPressed(GLFW_KEY_SPACE, false)) state.paused = !state.paused;
  if (ImGui::IsKeyPressed(GLFW_KEY_N)) state.stepOnce = true;
  if (ImGui::IsKeyPressed(GLFW_KEY_R, false)) state.resetRequested = true;
  if (ImGui::IsKeyPressed(GLFW_KEY_G, false)) d.showGrid = !d.showGrid;
  if (ImGui::IsKeyPressed(GLFW_KEY_X, false)) d.cutaway = !d.cutaway;
  if (ImGui::IsKeyPressed(GLFW_KEY_B, false)) d.show.boundary = !d.show.boundary;
  if (ImGui::IsKeyPressed(GLFW_KEY_O, false)) d.show.objects = !d.show.objects;
  if (ImGui::IsKeyPressed(GLFW_KEY_C, false))
    d.colour = render::ColourMode((int(d.colour) + 1) % 5);
  if (ImGui::IsKeyPressed(GLFW_KEY_L, false))
    d.look = d.look == render::Look::Liquid ? render::Look::Particles : render::Look::Liquid;
  if (ImGui::IsKeyPressed(GLFW_KEY_M, false)) d.objectSurfaces = !d.objectSurfaces;
}

// A kinematic object held by ctrl + left drag: the point of it the cursor took hold of moves
// in the plane that faces the camera through that point.
struct Grab {
  bool held = false;
  std::string name;
  Vec3d startCentre{0, 0, 0};     // steerObject's offsets are from here
  render::Vec3f handle{0, 0, 0};  // the point held, from the object's centre
};

render::Vec3f toVec3f(const std::array<double, 3>& v) {
  return {float(v[0]), float(v[1]), float(v[2])};
}

// Starts holding the kinematic object under the cursor, if there is one.
void grab(Simulation& sim, const Ray& ray, Grab& held, ViewerState& state) {
  const Scene& scene = sim.scene();
  std::vector<bool> kinematic(scene.objects.size());
  for (std::size_t o = 0; o < kinematic.size(); ++o)
    kinematic[o] = scene.objects[o].motion == ObjectMotion::Kinematic;
  const ParticleFrame solids = sim.solidFrame(false);
  // Within a fluid spacing of the ray: an object's particles are that far apart unless it sets
  // a spacing of its own.
  const float reach = float(scene.fluid.spacing);
  const std::optional<Pick> pick =
      pickObject(ray, solids.position, solids.object, kinematic, reach);
  if (!pick) return;
  const ObjectStats stats = sim.objectStats()[pick->object];
  const render::Vec3f point = render::add(ray.origin, render::scale(ray.direction, pick->distance));
  held = {true, stats.name, stats.startCentre,
          render::subtract(point, toVec3f(stats.centreOfMass))};
  if (!state.watching || state.watched != pick->object) state.watchedForce.clear();
  state.watching = true;
  state.watched = pick->object;
  state.watchedName = stats.name;
}

void steer(Simulation& sim, const render::OrbitCamera& camera, const Ray& ray, const Grab& held,
           ViewerState& state) {
  const render::Vec3f centre = toVec3f(sim.objectStats()[state.watched].centreOfMass);
  const auto target = dragTarget(camera, ray, render::add(centre, held.handle));
  if (!target) return;
  const render::Vec3f to = render::subtract(*target, held.handle);
  try {
    sim.steerObject(
        held.name,
        {to[0] - held.startCentre[0], to[1] - held.startCentre[1], to[2] - held.startCentre[2]},
        1.0 / 30.0);
  } catch (const InputError& e) {
    state.message = e.what();
  }
}

// Left drag turns the camera, right drag pans, the wheel zooms; ctrl + left drag holds the
// kinematic object under the cursor (the probe sphere, a clamp) and moves it.
void handleMouse(render::OrbitCamera& camera, Simulation& sim, Grab& held, int width, int height,
                 ViewerState& state) {
  const ImGuiIO& io = ImGui::GetIO();
  if (!io.MouseDown[0]) held.held = false;
  if (io.WantCaptureMouse) return;
  if (io.MouseWheel != 0.0f) camera.distance *= std::pow(0.9f, io.MouseWheel);
  if (io.MouseDown[0] && (io.KeyCtrl || held.held)) {
    const Ray ray = rayThroughPixel(camera, io.MousePos.x, io.MousePos.y, width, height);
    if (io.MouseClicked[0]) grab(sim, ray, held, state);
    if (held.held) steer(sim, camera, ray, held, state);
    return;
  }
  if (io.MouseDown[0]) {
    camera.yaw -= 0.005f * io.MouseDelta.x;
    camera.pitch = std::clamp(camera.pitch + 0.005f * io.MouseDelta.y, -1.5f, 1.5f);
  }
  if (io.MouseDown[1]) {
    // Along the screen's right and up at the target's depth.
    const float scale = 2.0f * camera.distance * std::tan(0.5f * camera.verticalFov) / height;
    const float cy = std::cos(camera.yaw), sy = std::sin(camera.yaw);
    const float sp = std::sin(camera.pitch), cp = std::cos(camera.pitch);
    const render::Vec3f right{cy, 0.0f, -sy};
    const render::Vec3f up{-sp * sy, cp, -sp * cy};
    for (int a = 0; a < 3; ++a)
      camera.target[a] += scale * (-io.MouseDelta.x * right[a] + io.MouseDelta.y * up[a]);
  }
}

// The force on the watched object, fluid's and contacts' together, kept for the panel's plot.
void watchForce(const Simulation& sim, ViewerState& state) {
  if (!state.watching) return;
  const ObjectStats o = sim.objectStats()[state.watched];
  double squared = 0.0;
  for (int a = 0; a < 3; ++a) squared += std::pow(o.fluidForce[a] + o.contactForce[a], 2);
  state.watchedForce.push_back(float(std::sqrt(squared)));
  constexpr std::size_t kKept = 300;
  if (state.watchedForce.size() > kKept)
    state.watchedForce.erase(state.watchedForce.begin(),
                             state.watchedForce.end() - std::ptrdiff_t(kKept));
}

// Steps toward real time, within a budget of wall time per display frame so the window stays
// responsive when the simulation cannot keep up.
void advance(Simulation& sim, ViewerState& state, double wallSeconds) {
  if (state.paused && !state.stepOnce) return;
  const double before = sim.time();
  const auto start = Clock::now();
  try {
    if (state.stepOnce) {
      sim.step();
      state.paused = true;
      state.stepOnce = false;
    } else {
      const double target = sim.time() + std::min(wallSeconds, 0.05);
      const auto deadline = start + std::chrono::milliseconds(25);
      do {
        sim.step(target);
        smooth(state.profile, sim.lastProfile(), 0.05);
      } while (sim.time() < target && Clock::now() < deadline);
    }
  } catch (const SimulationFailure& failure) {
    state.paused = true;
    state.message = std::string(failure.what()) + " (r resets)";
  }
  state.probes.add(sim.takeProbeRows());
  watchForce(sim, state);
  const double wall = std::chrono::duration<double>(Clock::now() - start).count();
  if (wall > 0.0) {
    const double factor = (sim.time() - before) / std::max(wall, wallSeconds);
    state.realTimeFactor += 0.1 * (factor - state.realTimeFactor);
  }
}

}  // namespace

void runViewer(const Scene& original, const ViewOptions& options) {
  const std::optional<render::ColourMode> mode = render::parseColourMode(options.colour);
  if (!mode)
    throw InputError("--colour: expected kind, density, pressure, speed or surface, got '" +
                     options.colour + "'");
  if (!options.look.empty() && options.look != "liquid" && options.look != "particles")
    throw InputError("--look: expected liquid or particles, got '" + options.look + "'");
  Scene scene = original;
  if (options.probe) addProbe(scene);
  Grab held;
  auto sim = std::make_unique<Simulation>(scene, options.simulation);

  GlfwSession glfw;
  const Window owned(options.width, options.height, "sph view: " + scene.name);
  GLFWwindow* window = owned.handle;
  ImGuiSession imgui(window);
  render::ParticleRenderer renderer;
  FluidFeed feed(renderer, *sim);
  renderer.setObjectSurfaces(sim->objectSurfaces());

  ViewerState state;
  state.fluidPath = feed.path();
  state.probes.reset(sim->probeColumns());
  state.draw.colour = *mode;
  state.draw.look =
      render::chooseLook(options.look, scene.render.look == FluidLook::Particles, *mode);
  state.draw.objectSurfaces = options.objectSurfaces;
  state.draw.liquid.colour = rgbOf(scene.render.colour);
  state.draw.liquid.absorption = rgbOf(scene.render.absorption);
  // The scene's own first kinematic object (the artery's clamp) is watched from the start.
  for (std::size_t o = 0; o < scene.objects.size(); ++o) {
    if (scene.objects[o].motion != ObjectMotion::Kinematic) continue;
    state.grabbable = true;
    if (state.watching || (options.probe && o + 1 == scene.objects.size())) continue;
    state.watching = true;
    state.watched = o;
    state.watchedName = scene.objects[o].name;
  }
  state.draw.show.boundary = false;  // walls hide the fluid; b shows them
  state.draw.particleRadius = float(0.5 * scene.fluid.spacing);
  state.draw.domain = boxOf(scene.domain.box);
  state.draw.gridCellSize = float(sim->calibration().supportRadius);
  state.draw.showDomain = true;
  render::OrbitCamera camera;
  camera.frame(state.draw.domain, float(options.width) / float(options.height));

  auto lastFrame = Clock::now();
  for (int shown = 1; !glfwWindowShouldClose(window); ++shown) {
    glfwPollEvents();
    const auto now = Clock::now();
    const double wallSeconds = std::chrono::duration<double>(now - lastFrame).count();
    lastFrame = now;
    if (wallSeconds > 0.0)
      state.framesPerSecond += 0.1 * (1.0 / wallSeconds - state.framesPerSecond);
    if (state.resetRequested) {
      sim = std::make_unique<Simulation>(scene, options.simulation);
      state.probes.reset(sim->probeColumns());
      state.watchedForce.clear();
      held.held = false;
      state.resetRequested = false;
      state.message.clear();
    }
    advance(*sim, state, wallSeconds);

    int width = 0, height = 0;
    glfwGetFramebufferSize(window, &width, &height);
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    handleKeys(state);
    handleMouse(camera, *sim, held, width, height, state);
    if (width > 0 && height > 0) {
      feed.feed(*sim, state.draw);
      renderer.draw(camera, state.draw, width, height);
    }
    drawPanel(*sim, state, renderer.rangeUsed());
    ImGui::Render();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());

    if (options.frames > 0 && shown >= options.frames) {
      if (!options.screenshot.empty())
        render::writePng(options.screenshot, width, height, render::readRgbPixels(width, height));
      break;
    }
    glfwSwapBuffers(window);
  }
}

}  // namespace sph::view
