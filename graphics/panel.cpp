// graphics/panel.cpp: the panel's life, input and frame, its draft and verdicts (panel.h). The
// verdict runs on a worker thread (std::async) on copies of the draft and the current state; the
// idle callback polls it, as it polls a divergence's diagnosis, and starts the next one when the
// draft changed meanwhile: at most one analysis runs, and the last change is always judged.

#include "graphics/panel.h"

#include <GL/freeglut.h>
#include <imgui.h>
#include <imgui_impl_glut.h>
#include <imgui_impl_opengl2.h>
#include <imgui_internal.h>  // ImGui::GetActiveID: whether a field is being typed in

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "graphics/panelstate.h"
#include "io/input.h"
#include "io/scenereader.h"
#include "model/model.h"

namespace jello {

bool panelBuilt() { return true; }

PanelState& panel(Viewer& v) { return *v.panel; }

namespace {

void zeroPinnedVelocities(const std::vector<int>& pinned, State* state) {
  const int n = state->points();
  for (int q : pinned) store(state->v(), q, n, Vec3{});
}

bool panelWanted(Viewer& v) { return v.panel && v.panel->open; }

// Whether the cursor at (x, y) is over the panel (as last drawn).
bool overPanel(Viewer& v, int x, int y) {
  return panelWanted(v) && x >= v.width - kPanelWidth && x < v.width && y >= 0 &&
         y < panel(v).height;
}

void startJob(Viewer& v) {
  PanelState& p = panel(v);
  World world = draftWorld(v, p.draft);
  if (!v.model.world.scene && !p.draft.physics) world.scene = nullptr;  // a course world as it is
  State state = v.state();
  zeroPinnedVelocities(p.draft.scene.pinned, &state);  // as applying the draft would
  p.job =
      std::async(std::launch::async, [world = std::move(world), state = std::move(state),
                                      run = p.draft.run] { return judgeStep(world, state, run); });
}

void askVerdict(Viewer& v) {
  PanelState& p = panel(v);
  // None while the panel is closed (it opens on the setup's own verdict); at most one at a time.
  if (!p.open || p.job.valid() || p.jobGeneration == p.generation) return;
  p.jobGeneration = p.generation;
  p.jobAsked = Clock::now();
  try {
    startJob(v);
  } catch (const std::bad_alloc&) {
    v.say("no memory for a copy of the world to judge the change on: none judged");
  }
}

// The verdict's line on stderr, as every message of the window: the tests read it there.
void announce(Viewer& v, const StepVerdict& verdict) {
  PanelState& p = panel(v);
  printError(textf("panel: %s verdict after %.3f s: %s", p.draft.changed ? "change's" : "setup's",
                   p.verdictSeconds, verdict.text.c_str()));
}

}  // namespace

Draft draftOf(Viewer& v) {
  Draft d;
  // The world without its field (the panel changes none, and a field may be gigabytes): the
  // field's buffer is lent out while the rest is copied, not copied itself. The model's terms
  // point into that buffer, which a move keeps where it is.
  ForceField field = std::move(v.model.world.field);
  d.world = v.model.world;
  v.model.world.field = std::move(field);
  if (v.model.world.scene) d.scene = *v.model.world.scene;
  d.run = {v.simulation.integrator(), v.simulation.dt(), v.n};
  return d;
}

World draftWorld(const Viewer& v, const Draft& draft) {
  World world = draft.world;
  world.field = v.model.world.field;
  world.scene = std::make_shared<const SceneSpec>(draft.scene);
  return world;
}

void draftChanged(Viewer& v, bool physics) {
  PanelState& p = panel(v);
  p.draft.changed = true;
  p.draft.physics = p.draft.physics || physics;
  ++p.generation;
  askVerdict(v);
}

void recountRun(Viewer& v) {
  const long long step = v.simulation.step();
  const double dt = v.simulation.dt();
  v.clock = FrameClock(v.pictures.fps, v.n, dt, step, v.time());
  if (v.saving) v.nextFrame = v.savedStep == step ? v.clock.nextAfter(step) : step;
  if (v.endTime && !v.ended)
    v.endStep = step + stepsForTime(std::max(0.0, *v.endTime - v.time()), dt).value_or(0);
}

// A diverged run given a change goes on from its last sane state: its diagnosis, if still under
// way, is let run out unread.
void resumeDiverged(Viewer& v) {
  if (!v.diverged) return;
  v.diverged = false;
  v.standing.clear();
  if (v.diagnosis.valid()) v.staleDiagnoses.push_back(std::move(v.diagnosis));
}

void applyDraft(Viewer& v, const RunSettings& run) {
  PanelState& p = panel(v);
  State state = v.state();
  if (p.draft.physics) {
    zeroPinnedVelocities(p.draft.scene.pinned, &state);
    // The simulation references v.model: the new model takes its place, and the simulation goes on
    // from the current state with the new run settings (Simulation::change).
    try {
      v.model = makeModel(draftWorld(v, p.draft), state);
    } catch (const std::bad_alloc&) {
      v.say("no memory for the changed world: nothing applied");
      return;
    }
    v.simulation.restore(state, v.simulation.step());
  }
  v.simulation.change(run);
  v.n = run.n;
  recountRun(v);
  v.initial = v.state();  // a divergence from here is diagnosed from here
  v.lastGood = v.state();
  resumeDiverged(v);
  const std::string what =
      textf("applied the changes: the run goes on with %s at dt %g s, %d steps a frame",
            integratorName(run.integrator), run.dt, run.n);
  p.draft = draftOf(v);
  ++p.generation;  // the setup as it now runs is judged afresh
  askVerdict(v);
  v.say(what + (v.paused ? " (paused: p runs on)" : ""));
}

void startPanel(Viewer& v) {
  v.panel = std::make_shared<PanelState>();
  PanelState& p = *v.panel;
  p.open = v.width >= kPanelOpenWidth && v.height >= kPanelOpenHeight;
  const char* trace = std::getenv("JELLO_PANEL_TRACE");
  p.trace = trace && std::strcmp(trace, "1") == 0;
  std::snprintf(p.saveName, sizeof p.saveName, "%s-saved.toml", v.stem.c_str());
  p.draft = draftOf(v);
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // no imgui.ini in the user's folder
  io.LogFilename = nullptr;
  ImGui::StyleColorsDark();
  ImGui_ImplGLUT_Init();
  ImGui_ImplOpenGL2_Init();
  askVerdict(v);  // the setup's own verdict, shown until something changes
}

void stopPanel(Viewer& v) {
  if (!v.panel) return;
  ImGui_ImplOpenGL2_Shutdown();
  ImGui_ImplGLUT_Shutdown();
  ImGui::DestroyContext();
  // A verdict under way is not waited for here (ESC closes the window at once): the viewer keeps
  // it, and waits for it once the window is gone.
  if (v.panel->job.valid()) v.verdictLeft = std::move(v.panel->job);
  v.panel.reset();
}

void togglePanel(Viewer& v) {
  if (!v.panel) return;
  v.panel->open = !v.panel->open;
  printError(v.panel->open ? "panel: open" : "panel: closed");
  askVerdict(v);  // the draft's, or the setup's, when none was judged while it was closed
}

void pollPanel(Viewer& v) {
  if (!v.panel) return;
  PanelState& p = panel(v);
  if (!p.job.valid() || p.job.wait_for(std::chrono::seconds(0)) != std::future_status::ready)
    return;
  try {
    p.verdict = p.job.get();
    p.verdictGeneration = p.jobGeneration;
    p.verdictSeconds = seconds(p.jobAsked, Clock::now());
    if (p.verdictGeneration == p.generation) announce(v, *p.verdict);
  } catch (const std::exception& e) {
    p.verdict.reset();
    v.say(std::string("the verdict on the change failed: ") + e.what());
  }
  askVerdict(v);  // the draft changed while this one was judged
}

// One ImGui frame: the panel's widgets (and what they do), drawn when `draw`.
void panelFrame(Viewer& v, bool draw) {
  panel(v).changed.clear();
  ImGuiIO& io = ImGui::GetIO();
  io.DisplaySize = ImVec2(static_cast<float>(v.width), static_cast<float>(v.height));
  ImGui_ImplOpenGL2_NewFrame();
  ImGui_ImplGLUT_NewFrame();  // ImGui::NewFrame too (this backend's version)
  if (panelWanted(v)) {
    ImGui::SetNextWindowPos(ImVec2(v.width - kPanelWidth, 0), ImGuiCond_Always);
    // As tall as its open sections, at most the window: the colour legend at the bottom right of
    // the picture shows below it while the sections below the jelly's are closed.
    ImGui::SetNextWindowSizeConstraints(ImVec2(kPanelWidth, 0),
                                        ImVec2(kPanelWidth, static_cast<float>(v.height)));
    ImGui::SetNextWindowBgAlpha(0.85f);
    const ImGuiWindowFlags flags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                   ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_AlwaysAutoResize;
    if (ImGui::Begin("jello panel (g hides it)", nullptr, flags)) {
      verdictSection(v);
      runSection(v);
      jellySection(v);
      contactSection(v);
      worldSection(v);
      viewSection(v);
      saveSection(v);
    }
    panel(v).height = ImGui::GetWindowHeight();
    ImGui::End();
  }
  if (!draw) {
    ImGui::EndFrame();
    return;
  }
  ImGui::Render();
  ImGui_ImplOpenGL2_RenderDrawData(ImGui::GetDrawData());
}

void drawPanel(Viewer& v) {
  if (v.panel) panelFrame(v, true);
}

// ---------------------------------------------------------------------------------------------
// Input: ImGui sees every event; the viewer those the panel does not take.

namespace {

enum InputGroup { kKeys, kSpecialKeys, kButtons };

// Before ImGui is told of a change to a key or button: a frame first when that one changed since
// the last (PanelState::changed).
void beforeChange(Viewer& v, InputGroup group, int code) {
  PanelState& p = panel(v);
  const std::pair<int, int> which{group, code};
  if (std::find(p.changed.begin(), p.changed.end(), which) != p.changed.end()) panelFrame(v, false);
  p.changed.push_back(which);
}

}  // namespace

bool panelKeyboard(Viewer& v, unsigned char key, int x, int y) {
  if (!v.panel) return false;
  beforeChange(v, kKeys, key);
  ImGui_ImplGLUT_KeyboardFunc(key, x, y);
  return panelWanted(v) && ImGui::GetIO().WantCaptureKeyboard;
}

void panelKeyboardUp(Viewer& v, unsigned char key, int x, int y) {
  if (!v.panel) return;
  beforeChange(v, kKeys, key);
  ImGui_ImplGLUT_KeyboardUpFunc(key, x, y);
}

bool panelSpecial(Viewer& v, int key, int x, int y) {
  if (!v.panel) return false;
  beforeChange(v, kSpecialKeys, key);
  ImGui_ImplGLUT_SpecialFunc(key, x, y);
  return panelWanted(v) && ImGui::GetIO().WantCaptureKeyboard;
}

void panelSpecialUp(Viewer& v, int key, int x, int y) {
  if (!v.panel) return;
  beforeChange(v, kSpecialKeys, key);
  ImGui_ImplGLUT_SpecialUpFunc(key, x, y);
}

bool panelMouse(Viewer& v, int button, int state, int x, int y) {
  if (!v.panel) return false;
  beforeChange(v, kButtons, button);
  ImGui_ImplGLUT_MouseFunc(button, state, x, y);
  PanelState& p = panel(v);
  // A release always reaches the viewer too: a drag begun outside the panel ends wherever it ends.
  if (state == GLUT_UP) {
    p.dragging = false;
    return false;
  }
  p.dragging = overPanel(v, x, y) || (panelWanted(v) && ImGui::GetIO().WantCaptureMouse);
  return p.dragging;
}

void panelWheel(Viewer& v, int wheel, int direction, int x, int y) {
  if (v.panel) ImGui_ImplGLUT_MouseWheelFunc(wheel, direction, x, y);
}

bool panelMotion(Viewer& v, int x, int y) {
  if (!v.panel) return false;
  ImGui_ImplGLUT_MotionFunc(x, y);
  return panel(v).dragging;  // a drag the panel took (a slider); the viewer's own go on
}

// ---------------------------------------------------------------------------------------------
// Widgets.

// A widget's name in the trace: its ID after "##", or its label.
std::string widgetName(const char* label) {
  const char* id = std::strstr(label, "##");
  return id ? id + 2 : label;
}

// Its name in messages: its label as shown, or its ID when it shows none.
std::string shownName(const char* label) {
  const std::size_t shown = std::strcspn(label, "#");
  return shown > 0 ? std::string(label, shown) : widgetName(label);
}

void traceItem(Viewer& v, const char* label) {
  PanelState& p = panel(v);
  if (!p.trace) return;
  const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
  const std::string place = textf("%d %d %d %d", static_cast<int>(a.x), static_cast<int>(a.y),
                                  static_cast<int>(b.x - a.x), static_cast<int>(b.y - a.y));
  std::string& last = p.traced[widgetName(label)];
  if (last == place) return;
  last = place;
  std::fprintf(stderr, "panel-trace: %s %s\n", widgetName(label).c_str(), place.c_str());
}

bool frictionFields(Viewer& v, const std::string& id, Friction* friction, bool speed) {
  const Friction before = *friction;
  bool changed = numberField(v, ("static friction##" + id + "mus").c_str(), &friction->muStatic, 0,
                             kMostFriction);
  changed |= numberField(v, ("dynamic friction##" + id + "mud").c_str(), &friction->muDynamic, 0,
                         kMostFriction);
  if (speed)
    changed |= numberField(v, ("friction speed, m/s##" + id + "eps").c_str(), &friction->speed, 0,
                           kLargestSceneNumber, true);
  if (const auto fault = frictionFault(*friction)) {
    v.say(std::string(fault->key) + " " + fault->why);
    *friction = before;
    return false;
  }
  return changed;
}

bool numberField(Viewer& v, const char* label, double* value, double lowest, double highest,
                 bool above) {
  PanelState& p = panel(v);
  const ImGuiID id = ImGui::GetID(label);
  std::string& text = p.fieldText[id];
  if (ImGui::GetActiveID() != id) {
    text.clear();
    appendNumber(text, *value);
  }
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%s", text.c_str());
  ImGui::InputText(label, buffer, sizeof buffer);  // every character kept: the reader judges
  text = buffer;
  traceItem(v, label);
  if (!ImGui::IsItemDeactivatedAfterEdit()) return false;
  double typed = 0;
  std::string why;
  if (!parseWorldNumber(text, &typed, &why) || !(above ? typed > lowest : typed >= lowest) ||
      typed > highest) {
    v.say(shownName(label) + ": " + (why.empty() ? "" : why + "; ") + "expected a number from " +
          std::string(above ? "above " : "") + figureText(lowest) + " to " + figureText(highest));
    return false;
  }
  if (typed == *value) return false;
  *value = typed;
  return true;
}

bool integerField(Viewer& v, const char* label, int* value, int lowest, int highest) {
  const ImGuiID id = ImGui::GetID(label);
  PanelState& p = panel(v);
  std::string& text = p.fieldText[id];
  if (ImGui::GetActiveID() != id) text = std::to_string(*value);
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%s", text.c_str());
  ImGui::InputText(label, buffer, sizeof buffer);
  text = buffer;
  traceItem(v, label);
  if (!ImGui::IsItemDeactivatedAfterEdit()) return false;
  long long typed = 0;
  std::string why;
  if (!parseWorldInteger(text, &typed, &why) || typed < lowest || typed > highest) {
    v.say(shownName(label) + ": " + (why.empty() ? "" : why + "; ") +
          "expected a whole number from " + std::to_string(lowest) + " to " +
          std::to_string(highest));
    return false;
  }
  if (typed == *value) return false;
  *value = static_cast<int>(typed);
  return true;
}

bool vectorField(Viewer& v, const char* shown, const std::string& name, Vec3* value,
                 double largest) {
  bool changed = false;
  ImGui::PushItemWidth(80);
  const char* axes[] = {"x", "y", "z"};
  double* parts[] = {&value->x, &value->y, &value->z};
  for (int axis = 0; axis < 3; ++axis) {
    if (axis > 0) ImGui::SameLine();
    // Shown after the last box; known (the trace, messages) as NAME.x, NAME.y, NAME.z.
    const std::string id = std::string(axis == 2 ? shown : "") + "##" + name + "." + axes[axis];
    changed |= numberField(v, id.c_str(), parts[axis], -largest, largest);
  }
  ImGui::PopItemWidth();
  return changed;
}

}  // namespace jello
