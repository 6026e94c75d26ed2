// The viewer's Dear ImGui panel: live figures, the draw settings, and the parameters a user may
// change while the simulation runs.
#pragma once

#include "sph/simulation.hpp"
#include "viewer_state.hpp"

namespace sph::view {

// Draws the panel for this frame; buttons and edits go into `state` and `sim`. Call between
// ImGui::NewFrame and ImGui::Render.
void drawPanel(Simulation& sim, ViewerState& state, const render::ValueRange& colourRange);

}  // namespace sph::view
