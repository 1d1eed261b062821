#pragma once
// The panel's sections, one function each (ui/*_section.cpp). Internal to ui/.
#include <cstddef>
#include <string>
#include <vector>

#include "ui/actions.h"
#include "ui/format.h"
#include "ui/panel.h"
#include "ui/panel_state.h"

namespace isotrack::ui {

void dataSection(const PanelState& state, PanelScratch& scratch, std::vector<Action>& actions);
void extractionSection(const PanelState& state, std::vector<Action>& actions);
void timeSection(const PanelState& state, std::vector<Action>& actions);
void timePlot(const PanelState& state);  // the selected surface's area and volume over the steps seen
void growthSection(const PanelState& state, std::vector<Action>& actions);
void surfacesSection(const PanelState& state, PanelScratch& scratch, std::vector<Action>& actions);
void viewSection(const PanelState& state, std::vector<Action>& actions);
void statsSection(const PanelState& state);
void treeSection(const PanelState& state, std::vector<Action>& actions);

}  // namespace isotrack::ui
