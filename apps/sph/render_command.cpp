// sph render: a finished run's frames as PNG images (DIR/images/frame_NNNNN.png) and an MP4
// video (DIR/video.mp4), drawn offscreen (EGL) by the renderer the viewer uses.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "camera.hpp"
#include "colour_map.hpp"
#include "commands.hpp"
#include "offscreen_context.hpp"
#include "particle_renderer.hpp"
#include "png_writer.hpp"
#include "render_run_info.hpp"
#include "sph/error.hpp"
#include "sph/io/frame_reader.hpp"
#include "sph/io/object_surface_file.hpp"
#include "video.hpp"

namespace sph::cli {

namespace fs = std::filesystem;
using render::Box3f;

namespace {

// The frames that choose the colour range and the camera: up to nine, evenly spread, the first
// and last among them, so both hold still for the whole video.
std::vector<ParticleFrame> sampleFrames(const std::vector<fs::path>& frames) {
  const std::size_t count = std::min<std::size_t>(frames.size(), 9);
  std::vector<ParticleFrame> sample;
  for (std::size_t k = 0; k < count; ++k) {
    const std::size_t index = count == 1 ? 0 : k * (frames.size() - 1) / (count - 1);
    sample.push_back(io::readFrame(frames[index]));
  }
  return sample;
}

void growBox(Box3f& box, const ParticleFrame& frame) {
  for (std::size_t i = 0; i < frame.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      box.min[c] = std::min(box.min[c], frame.position[3 * i + c]);
      box.max[c] = std::max(box.max[c], frame.position[3 * i + c]);
    }
}

Box3f emptyBox() {
  const float inf = std::numeric_limits<float>::infinity();
  return {{inf, inf, inf}, {-inf, -inf, -inf}};
}

bool isEmpty(const Box3f& box) {
  return !(box.min[0] <= box.max[0]);
}

// Without summary.json: the spacing of a lattice that fills the fluid's bounding box.
float estimateSpacing(const ParticleFrame& frame) {
  Box3f box = emptyBox();
  growBox(box, frame);
  if (isEmpty(box) || frame.size() < 2) return 0.01f;
  const float volume = std::max(box.max[0] - box.min[0], 1e-6f) *
                       std::max(box.max[1] - box.min[1], 1e-6f) *
                       std::max(box.max[2] - box.min[2], 1e-6f);
  return std::cbrt(volume / static_cast<float>(frame.size()));
}

void appendParticles(ParticleFrame& frame, const ParticleFrame& more) {
  auto append = [](auto& to, const auto& from) { to.insert(to.end(), from.begin(), from.end()); };
  append(frame.id, more.id);
  append(frame.position, more.position);
  append(frame.velocity, more.velocity);
  append(frame.density, more.density);
  append(frame.pressure, more.pressure);
  append(frame.kind, more.kind);
  append(frame.object, more.object);
  append(frame.surface, more.surface);
}

const char* unitOf(render::ColourMode mode) {
  switch (mode) {
    case render::ColourMode::Density:
      return " kg/m3";
    case render::ColourMode::Pressure:
      return " Pa";
    case render::ColourMode::Speed:
      return " m/s";
    default:
      return "";
  }
}

// Images of an earlier, longer render would otherwise end up in the video.
void clearImages(const fs::path& images) {
  std::error_code error;
  fs::create_directories(images, error);
  if (error) throw InputError(images.string() + ": cannot create: " + error.message());
  for (const fs::directory_entry& entry : fs::directory_iterator(images)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("frame_", 0) == 0 && entry.path().extension() == ".png")
      fs::remove(entry.path());
  }
}

std::vector<const ParticleFrame*> frames(const std::vector<ParticleFrame>& sample,
                                         const ParticleFrame& walls) {
  std::vector<const ParticleFrame*> all;
  for (const ParticleFrame& frame : sample) all.push_back(&frame);
  all.push_back(&walls);
  return all;
}

struct Scene {
  render::DrawSettings settings;
  render::OrbitCamera camera;
  ParticleFrame walls;  // empty unless shown
};

Scene prepareScene(const RenderOptions& options, const io::RunFrameFiles& files,
                   const RenderRunInfo& info) {
  Scene scene;
  render::DrawSettings& settings = scene.settings;
  settings.colour = render::parseColourMode(options.colour).value_or(render::ColourMode::Kind);
  const std::vector<ParticleFrame> sample = sampleFrames(files.frames);
  if (options.range.size() == 2) {
    settings.range = render::ValueRange{float(options.range[0]), float(options.range[1])};
  } else if (render::usesRange(settings.colour)) {
    std::vector<const ParticleFrame*> frames;
    for (const ParticleFrame& frame : sample) frames.push_back(&frame);
    settings.range = render::rangeFromFrames(frames, settings.colour);
  }
  settings.particleRadius = 0.5f * info.spacing.value_or(estimateSpacing(sample.front()));
  settings.look =
      render::chooseLook(options.look, info.look.value_or("") == "particles", settings.colour);
  if (info.liquidColour) {
    const render::Vec3f& c = *info.liquidColour;
    settings.liquid.colour = render::Rgb{c[0], c[1], c[2]};
  }
  if (info.absorption) {
    const render::Vec3f& a = *info.absorption;
    settings.liquid.absorption = render::Rgb{a[0], a[1], a[2]};
  }
  if (options.boundary && !files.boundary.empty()) scene.walls = io::readFrame(files.boundary);

  Box3f particles = emptyBox();
  for (const ParticleFrame* frame : frames(sample, scene.walls)) growBox(particles, *frame);
  if (isEmpty(particles)) particles = info.domain.value_or(Box3f{{0, 0, 0}, {1, 1, 1}});
  settings.domain = info.domain.value_or(particles);
  settings.showGrid = options.grid;
  settings.cutaway = options.cutaway;
  settings.objectSurfaces = options.objects == "surfaces";
  settings.showDomain = options.grid;
  settings.gridCellSize = info.supportRadius.value_or(4.0f * settings.particleRadius);
  // Framed on the particles (and the domain when its grid is shown), not on the domain alone: a
  // domain is often far larger than what moves in it.
  // The colour bar takes the right edge: frame as if the picture were a fifth narrower.
  const bool bar = render::usesRange(settings.colour) && settings.showColourBar &&
                   settings.look == render::Look::Particles;
  const float aspect = float(options.width) / float(options.height) * (bar ? 0.8f : 1.0f);
  // What has left the domain (a piece torn off a vessel, falling away) is not what the
  // picture is of.
  const auto inDomain = [&](const float* p) {
    if (!info.domain) return true;
    const Box3f& d = *info.domain;
    for (int c = 0; c < 3; ++c) {
      const float margin = 0.1f * (d.max[c] - d.min[c]);
      if (p[c] < d.min[c] - margin || p[c] > d.max[c] + margin) return false;
    }
    return true;
  };
  std::vector<render::Vec3f> points;
  for (const ParticleFrame* frame : frames(sample, scene.walls))
    for (std::size_t i = 0; i < frame->size(); ++i)
      if (inDomain(&frame->position[3 * i]))
        points.push_back(
            {frame->position[3 * i], frame->position[3 * i + 1], frame->position[3 * i + 2]});
  if (options.grid)
    for (int c = 0; c < 8; ++c)
      points.push_back({c & 1 ? settings.domain.max[0] : settings.domain.min[0],
                        c & 2 ? settings.domain.max[1] : settings.domain.min[1],
                        c & 4 ? settings.domain.max[2] : settings.domain.min[2]});
  if (points.empty())
    scene.camera.frame(settings.domain, aspect, float(options.yaw), float(options.pitch));
  else
    scene.camera.frame(points, aspect, float(options.yaw), float(options.pitch));
  return scene;
}

void printPlan(const RenderOptions& options, const io::RunFrameFiles& files, const Scene& scene,
               const render::OffscreenContext& context) {
  const render::DrawSettings& s = scene.settings;
  if (s.look == render::Look::Liquid)
    std::printf("rendering %zu frames of %s at %dx%d, the fluid as a liquid surface",
                files.frames.size(), options.dir.c_str(), options.width, options.height);
  else
    std::printf("rendering %zu frames of %s at %dx%d, colour by %s", files.frames.size(),
                options.dir.c_str(), options.width, options.height,
                render::colourModeName(s.colour));
  if (s.range && render::usesRange(s.colour) && s.look == render::Look::Particles)
    std::printf(" from %.6g%s (bottom of the colour bar) to %.6g%s (top)", s.range->min,
                unitOf(s.colour), s.range->max, unitOf(s.colour));
  std::printf("\n  with %s\n", context.description().c_str());
  std::fflush(stdout);
}

}  // namespace

bool rendererBuilt() {
  return true;
}

int renderCommand(const RenderOptions& options) {
  const fs::path dir = options.dir;
  const io::RunFrameFiles files = io::listRunFrames(dir);
  const RenderRunInfo info = readRenderRunInfo(dir);
  const Scene scene = prepareScene(options, files, info);

  render::OffscreenContext context(options.width, options.height);
  render::ParticleRenderer renderer;
  if (scene.settings.objectSurfaces && !files.objectSurfaces.empty())
    renderer.setObjectSurfaces(io::readObjectSurfaces(files.objectSurfaces));
  if (!options.quiet) printPlan(options, files, scene, context);
  const fs::path images = dir / "images";
  clearImages(images);

  const auto start = std::chrono::steady_clock::now();
  std::size_t reported = 0;
  for (std::size_t k = 0; k < files.frames.size(); ++k) {
    ParticleFrame frame = io::readFrame(files.frames[k]);
    appendParticles(frame, scene.walls);
    renderer.setParticles(frame);
    context.bindForDrawing();
    renderer.draw(scene.camera, scene.settings, options.width, options.height);
    context.resolveForReading();
    char name[32];
    std::snprintf(name, sizeof name, "frame_%05zu.png", k);
    render::writePng(images / name, options.width, options.height,
                     render::readRgbPixels(options.width, options.height));
    const std::size_t tenth = (k + 1) * 10 / files.frames.size();
    if (!options.quiet && tenth > reported) {
      reported = tenth;
      std::printf("  %zu/%zu images\n", k + 1, files.frames.size());
      std::fflush(stdout);
    }
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!options.quiet)
    std::printf("images: %s/frame_00000.png ... (%zu, %.2f s each)\n", images.c_str(),
                files.frames.size(), seconds / double(files.frames.size()));
  if (options.noVideo) return kExitOk;

  const double fps = options.fps > 0 ? options.fps : info.fps.value_or(30.0);
  const fs::path video = dir / "video.mp4";
  try {
    render::encodeVideo((images / "frame_%05d.png").string(), fps, video);
  } catch (const render::VideoError& e) {
    // The images are written; the video, one of the results, is not: exit 4 like any output
    // that could not be written.
    std::fprintf(stderr, "error: no video: %s\nthe images are in %s\n", e.what(), images.c_str());
    return kExitOutputFailed;
  }
  if (!options.quiet) std::printf("video:  %s (%g frames per second)\n", video.c_str(), fps);
  return kExitOk;
}

}  // namespace sph::cli
