// graphics/panelstate.h: the panel's state (panel.h) and what its files share: the draft of the
// changes not yet applied, the verdict on it from the worker thread, the fields' texts, and the
// widgets the sections are made of. Only in a build with Dear ImGui; not for use outside
// graphics/panel*.cpp.
#pragma once

#include <imgui.h>

#include <chrono>
#include <future>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "analysis/stepverdict.h"
#include "graphics/viewerstate.h"
#include "model/scenespec.h"

namespace jello {

constexpr float kPanelWidth = 380;  // pixels, at the window's right edge
constexpr std::size_t kSaveNameBytes = 512;

// Changes to the physics and to the step wait in a draft, judged before they are applied.
struct Draft {
  World world;      // its scene: `scene`, once the draft is applied
  SceneSpec scene;  // a copy of the world's (an empty one for a course world)
  RunSettings run;  // integrator and dt (n applies at once)
  bool changed = false;
  bool physics = false;  // beyond the run settings: the model is made again when applied
};

struct PanelState {
  bool open = false;
  float height = 0;       // pixels, as last drawn
  bool dragging = false;  // the mouse button down was pressed on the panel
  // The keys and buttons (group, code) whose state changed since ImGui's last frame: this ImGui
  // (1.86) reads their states once a frame, so a second change before the next frame (a quick
  // click, a synthetic key) would be lost; a frame is run first then (panel.cpp).
  std::vector<std::pair<int, int>> changed;
  bool trace = false;  // JELLO_PANEL_TRACE: each widget's place on stderr (the window tests)
  std::map<std::string, std::string> traced;
  std::map<ImGuiID, std::string> fieldText;  // the text of a number field while typed in
  Draft draft;
  int jelly = 0;  // the jelly the jelly section shows (several jellies)

  // The verdicts: on the draft (or, with nothing changed, the setup as it runs), on a worker
  // thread.
  long long generation = 0;  // counts the draft's changes
  std::future<StepVerdict> job;
  long long jobGeneration = -1;
  Clock::time_point jobAsked;  // when the change the job judges was made
  std::optional<StepVerdict> verdict;
  long long verdictGeneration = -1;
  double verdictSeconds = 0;  // from that change to its verdict

  Vec3 pinLower{-2, -2, -2}, pinUpper{2, 2, 2};  // the region the pin button pins
  char saveName[kSaveNameBytes] = {};
  bool replace = false;
};

// The panel's state; made by startPanel.
PanelState& panel(Viewer& v);

// One ImGui frame of the panel: its widgets and what they do, drawn when `draw` (panel.cpp).
void panelFrame(Viewer& v, bool draw);

// The draft from the setup as it runs; the draft made the setup (a new model where its physics
// changed, the run settings in every case), from the current state.
Draft draftOf(Viewer& v);
// The world the draft makes: its scene, and the field of the world as it runs.
World draftWorld(const Viewer& v, const Draft& draft);
void applyDraft(Viewer& v, const RunSettings& run);
// The frames' clock, the next frame to save and the end of --time counted again from the current
// step, at the run's dt and steps a frame.
void recountRun(Viewer& v);
// Marks the draft changed (`physics`: beyond the run settings) and asks for its verdict.
void draftChanged(Viewer& v, bool physics);

// Widgets. Each records its place for the trace under `label` (the text after "##" in ImGui's
// terms is not shown). numberField: a number typed in the world files' grammar and checked against
// [lowest, highest] (lowest itself excluded when `above`); true when a new value was entered.
void traceItem(Viewer& v, const char* label);
bool numberField(Viewer& v, const char* label, double* value, double lowest, double highest,
                 bool above = false);
// A whole number typed in the world files' grammar, checked against [lowest, highest].
bool integerField(Viewer& v, const char* label, int* value, int lowest, int highest);
bool vectorField(Viewer& v, const char* shown, const std::string& name, Vec3* value,
                 double largest);
// Friction's fields (IDs `id` + mus, mud and, with `speed`, eps), kept to friction's rule
// (model/obstacle.h frictionFault, the reader's): a value that breaks it is refused and said, as
// the reader would; true when one changed.
bool frictionFields(Viewer& v, const std::string& id, Friction* friction, bool speed);

// The sections (panelsections.cpp, panelworld.cpp).
void runSection(Viewer& v);
void jellySection(Viewer& v);
void contactSection(Viewer& v);
void worldSection(Viewer& v);
void viewSection(Viewer& v);
void verdictSection(Viewer& v);
void saveSection(Viewer& v);

}  // namespace jello
