#include "view_panel.hpp"

#include <imgui.h>

#include <cfloat>
#include <cstdio>
#include <string>
#include <vector>

#include "colour_map.hpp"
#include "sph/error.hpp"

namespace sph::view {

namespace {

void figures(const Simulation& sim, const ViewerState& state) {
  const Calibration& c = sim.calibration();
  ImGui::Text("%s on %s", sim.scene().name.c_str(), sim.backendName());
  ImGui::PushTextWrapPos(0.0f);
  ImGui::TextDisabled("%s", state.fluidPath.c_str());
  ImGui::PopTextWrapPos();
  ImGui::Text("fluid %llu   walls %llu   objects %llu", (unsigned long long)sim.fluidCount(),
              (unsigned long long)c.boundaryParticles, (unsigned long long)c.objectParticles);
  ImGui::Text("t = %.4f s   step %llu   dt = %.2e s", sim.time(),
              (unsigned long long)sim.stepCount(), sim.lastDt());
  ImGui::Text("simulated / real time: %.3f   display %.0f fps", state.realTimeFactor,
              state.framesPerSecond);
  if (sim.leakedCount() > 0 || sim.removedCount() > 0)
    ImGui::Text("leaked %llu   removed %llu", (unsigned long long)sim.leakedCount(),
                (unsigned long long)sim.removedCount());
  const StepProfile& p = state.profile;
  if (ImGui::BeginTable("stages", 2)) {
    const std::pair<const char*, double> rows[] = {{"step", p.total()},
                                                   {"  grid", p.buildGrid},
                                                   {"  density", p.densityPressure},
                                                   {"  forces", p.forces},
                                                   {"  interaction", p.interaction},
                                                   {"  time step", p.timeStep},
                                                   {"  integrate", p.integrate},
                                                   {"  objects", p.objects}};
    for (const auto& row : rows) {
      ImGui::TableNextRow();
      ImGui::TableSetColumnIndex(0);
      ImGui::TextUnformatted(row.first);
      ImGui::TableSetColumnIndex(1);
      ImGui::Text("%8.3f ms", row.second);
    }
    ImGui::EndTable();
  }
}

void controls(ViewerState& state) {
  if (ImGui::Button(state.paused ? "Run (space)" : "Pause (space)")) state.paused = !state.paused;
  ImGui::SameLine();
  if (ImGui::Button("Step (n)")) state.stepOnce = true;
  ImGui::SameLine();
  if (ImGui::Button("Reset (r)")) state.resetRequested = true;
}

// A horizontal strip of the sequential map, with its end values.
void colourBar(const render::ValueRange& range) {
  ImDrawList* list = ImGui::GetWindowDrawList();
  const ImVec2 at = ImGui::GetCursorScreenPos();
  const float width = ImGui::GetContentRegionAvail().x, height = 14.0f;
  const int segments = 32;
  for (int k = 0; k < segments; ++k) {
    const auto colour = [&](int s) {
      const float v = range.min + (range.max - range.min) * float(s) / segments;
      const render::Rgb c = render::mapValue(v, range);
      return ImGui::ColorConvertFloat4ToU32(ImVec4(c.r, c.g, c.b, 1.0f));
    };
    const float x0 = at.x + width * k / segments, x1 = at.x + width * (k + 1) / segments;
    list->AddRectFilledMultiColor(ImVec2(x0, at.y), ImVec2(x1, at.y + height), colour(k),
                                  colour(k + 1), colour(k + 1), colour(k));
  }
  ImGui::Dummy(ImVec2(width, height));
  ImGui::Text("%.4g", range.min);
  ImGui::SameLine(width - 60.0f);
  ImGui::Text("%.4g", range.max);
}

void drawSettings(ViewerState& state, const render::ValueRange& range) {
  render::DrawSettings& d = state.draw;
  const render::ColourMode modes[] = {render::ColourMode::Kind, render::ColourMode::Density,
                                      render::ColourMode::Pressure, render::ColourMode::Speed,
                                      render::ColourMode::Surface};
  if (ImGui::BeginCombo("colour (c)", render::colourModeName(d.colour))) {
    for (render::ColourMode mode : modes)
      if (ImGui::Selectable(render::colourModeName(mode), mode == d.colour)) d.colour = mode;
    ImGui::EndCombo();
  }
  bool liquid = d.look == render::Look::Liquid;
  if (ImGui::Checkbox("liquid surface (l)", &liquid))
    d.look = liquid ? render::Look::Liquid : render::Look::Particles;
  if (render::usesRange(d.colour) && !liquid) colourBar(range);
  ImGui::Checkbox("fluid", &d.show.fluid);
  ImGui::SameLine();
  ImGui::Checkbox("walls (b)", &d.show.boundary);
  ImGui::SameLine();
  ImGui::Checkbox("objects (o)", &d.show.objects);
  ImGui::SameLine();
  ImGui::Checkbox("as surfaces (m)", &d.objectSurfaces);
  ImGui::Checkbox("cut away (x)", &d.cutaway);
  ImGui::SameLine();
  ImGui::Checkbox("grid (g)", &d.showGrid);
  ImGui::SameLine();
  ImGui::Checkbox("domain", &d.showDomain);
}

// Edits apply when the user lets go of a field, so a drag does not recalibrate every frame.
void parameters(Simulation& sim, ViewerState& state) {
  LiveParameters& editing = state.editing;
  if (!ImGui::IsAnyItemActive()) editing = sim.liveParameters();
  bool changed = false;
  ImGui::DragScalar("viscosity", ImGuiDataType_Double, &editing.viscosity, 0.001f);
  changed |= ImGui::IsItemDeactivatedAfterEdit();
  ImGui::DragScalar("stiffness", ImGuiDataType_Double, &editing.stiffness,
                    float(0.01 * editing.stiffness));
  changed |= ImGui::IsItemDeactivatedAfterEdit();
  ImGui::DragScalarN("gravity", ImGuiDataType_Double, editing.gravity.data(), 3, 0.05f);
  changed |= ImGui::IsItemDeactivatedAfterEdit();
  ImGui::DragScalar("surface tension", ImGuiDataType_Double, &editing.surfaceTension, 0.001f);
  changed |= ImGui::IsItemDeactivatedAfterEdit();
  if (!sim.scene().objects.empty()) {
    ImGui::DragScalar("influence ratio", ImGuiDataType_Double, &editing.influenceRatio, 0.01f);
    changed |= ImGui::IsItemDeactivatedAfterEdit();
  }
  if (!changed) return;
  try {
    sim.setLiveParameters(editing);
    state.message.clear();
  } catch (const InputError& e) {
    state.message = e.what();
  }
}

// Each probe's latest reading, and the pressures, levels and forces over the last rows.
void probes(const ProbeReadings& readings) {
  ImGui::Text("at t = %.3f s", readings.latestTime());
  for (std::size_t c = 0; c < readings.columns().size(); ++c) {
    const std::vector<float>& h = readings.history(c);
    const std::string& name = readings.columns()[c];
    char value[32] = "-";
    if (!h.empty()) std::snprintf(value, sizeof value, "%.4g", double(h.back()));
    if (ProbeReadings::plotted(name) && !h.empty()) {
      ImGui::PlotLines(name.c_str(), h.data(), int(h.size()), 0, value, FLT_MAX, FLT_MAX,
                       ImVec2(0.0f, 36.0f));
    } else {
      ImGui::Text("%s  %s", name.c_str(), value);
    }
  }
}

// The fluid's and the other objects' push on the object last grabbed, over recent frames.
void watchedForce(const ViewerState& state) {
  const std::vector<float>& h = state.watchedForce;
  char value[32] = "-";
  if (!h.empty()) std::snprintf(value, sizeof value, "%.4g N", double(h.back()));
  const std::string label = "on " + state.watchedName;
  if (h.empty()) {
    ImGui::Text("%s  %s", label.c_str(), value);
    return;
  }
  ImGui::PlotLines(label.c_str(), h.data(), int(h.size()), 0, value, 0.0f, FLT_MAX,
                   ImVec2(0.0f, 48.0f));
}

}  // namespace

void smooth(StepProfile& into, const StepProfile& latest, double w) {
  const auto mix = [w](double& a, double b) { a += w * (b - a); };
  mix(into.buildGrid, latest.buildGrid);
  mix(into.densityPressure, latest.densityPressure);
  mix(into.divergenceSolve, latest.divergenceSolve);
  mix(into.forces, latest.forces);
  mix(into.interaction, latest.interaction);
  mix(into.timeStep, latest.timeStep);
  mix(into.densitySolve, latest.densitySolve);
  mix(into.integrate, latest.integrate);
  mix(into.objects, latest.objects);
  mix(into.wallForces, latest.wallForces);
  mix(into.flow, latest.flow);
  mix(into.probes, latest.probes);
  mix(into.exchange, latest.exchange);
}

void drawPanel(Simulation& sim, ViewerState& state, const render::ValueRange& colourRange) {
  ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(340, 0), ImGuiCond_FirstUseEver);
  ImGui::Begin("sph");
  figures(sim, state);
  controls(state);
  if (ImGui::CollapsingHeader("view", ImGuiTreeNodeFlags_DefaultOpen))
    drawSettings(state, colourRange);
  if (ImGui::CollapsingHeader("parameters", ImGuiTreeNodeFlags_DefaultOpen)) parameters(sim, state);
  if (!state.probes.columns().empty() &&
      ImGui::CollapsingHeader("probes", ImGuiTreeNodeFlags_DefaultOpen))
    probes(state.probes);
  if (state.watching && ImGui::CollapsingHeader("force", ImGuiTreeNodeFlags_DefaultOpen))
    watchedForce(state);
  ImGui::TextDisabled("left drag: turn   right drag: pan   wheel: zoom");
  if (state.grabbable) ImGui::TextDisabled("ctrl + left drag: move a kinematic object");
  if (!state.message.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
    ImGui::TextWrapped("%s", state.message.c_str());
    ImGui::PopStyleColor();
  }
  ImGui::End();
}

}  // namespace sph::view
