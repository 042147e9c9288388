// graphics/panelsections.cpp: the panel's sections of the verdict, the run, the jelly, the
// contacts, the view and saving (panelstate.h). A change to the physics or the step goes into the
// draft; the rest (steps per frame, pause, pacing, the view) applies at once.

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "graphics/panelstate.h"
#include "io/scenereader.h"
#include "io/scenewriter.h"
#include "model/model.h"

namespace jello {

namespace {

ImVec4 verdictColour(Verdict verdict) {
  switch (verdict) {
    case Verdict::Stable:
      return ImVec4(0.45f, 0.9f, 0.45f, 1);
    case Verdict::NearLimit:
      return ImVec4(1.0f, 0.8f, 0.3f, 1);
    case Verdict::Unstable:
      break;
  }
  return ImVec4(1.0f, 0.4f, 0.35f, 1);
}

bool button(Viewer& v, const char* label) {
  const bool pressed = ImGui::Button(label);
  traceItem(v, label);
  return pressed;
}

bool checkbox(Viewer& v, const char* label, bool* value) {
  const bool changed = ImGui::Checkbox(label, value);
  traceItem(v, label);
  return changed;
}

void discardDraft(Viewer& v) {
  PanelState& p = panel(v);
  p.draft = draftOf(v);
  draftChanged(v, false);
  p.draft.changed = false;
  v.say("the changes were discarded");
}

// With several jellies the world's mass, kElastic and dElastic are the first jelly's (the scene
// reader's rule, which a saved scene read back keeps).
void mirrorFirstJelly(Draft& d) {
  if (d.scene.jellies.empty()) return;
  const JellySpec& first = d.scene.jellies[0];
  d.world.mass = first.mass;
  d.world.kElastic = first.springs.k[0];
  d.world.dElastic = first.springs.d[0];
}

// A jelly's mass, springs and material in the draft: the world's and its scene's for one jelly,
// its own for several.
struct JellyFields {
  double* mass;
  SpringConstants springs;
  Material* material;
  const Body* body;
};

JellyFields jellyFields(Draft& d, int jelly) {
  const Body& body = d.scene.body ? *d.scene.body : courseBody();
  if (d.scene.jellies.empty()) {
    const SpringConstants springs = d.scene.springs
                                        ? *d.scene.springs
                                        : SpringConstants::same(d.world.kElastic, d.world.dElastic);
    return {&d.world.mass, springs, &d.scene.material, &body};
  }
  JellySpec& spec = d.scene.jellies[jelly];
  return {&spec.mass, spec.springs, &spec.material, body.parts[jelly].get()};
}

// A jelly's springs in the draft; the world's kElastic, dElastic and mass kept as the scene reader
// keeps them: one jelly's when its kinds are equal, the first jelly's of several.
void setSprings(Draft& d, int jelly, const SpringConstants& springs) {
  if (d.scene.jellies.empty()) {
    d.scene.springs = springs;
    if (springs.uniform()) d.world.kElastic = springs.k[0], d.world.dElastic = springs.d[0];
    return;
  }
  d.scene.jellies[jelly].springs = springs;
  mirrorFirstJelly(d);
}

void springFields(Viewer& v, Draft& d, JellyFields& f) {
  PanelState& p = panel(v);
  if (numberField(v, "mass, kg a point##jelly.mass", f.mass, 0, kLargestSceneNumber, true)) {
    mirrorFirstJelly(d);
    draftChanged(v, true);
  }
  const char* names[2][kSpringKinds] = {
      {"structural stiffness, N/m##jelly.k.structural", "shear stiffness##jelly.k.shear",
       "bend stiffness##jelly.k.bend"},
      {"structural damping, N s/m##jelly.d.structural", "shear damping##jelly.d.shear",
       "bend damping##jelly.d.bend"}};
  for (int which = 0; which < 2; ++which)
    for (int kind = 0; kind < kSpringKinds; ++kind) {
      double& value = which == 0 ? f.springs.k[kind] : f.springs.d[kind];
      if (numberField(v, names[which][kind], &value, 0, kLargestSceneNumber)) {
        setSprings(d, p.jelly, f.springs);
        draftChanged(v, true);
      }
    }
}

void elementFields(Viewer& v, Draft& d, JellyFields& f) {
  Material& m = *f.material;
  bool changed = numberField(v, "Young's modulus, Pa##jelly.E", &m.youngsModulus, 0,
                             kLargestSceneNumber, true);
  changed |= numberField(v, "Poisson's ratio##jelly.nu", &m.poissonRatio,
                         smallestPoissonRatio(m.kind), kLargestPoissonRatio);
  changed |= numberField(v, "density, kg/m^3##jelly.density", &m.density, kSmallestDensity,
                         kLargestDensity);
  changed |=
      numberField(v, "mass damping, 1/s##jelly.alpha", &m.massDamping, 0, kLargestSceneNumber);
  changed |= numberField(v, "stiffness damping, s##jelly.beta", &m.stiffnessDamping, 0,
                         kLargestSceneNumber);
  if (!changed) return;
  *f.mass = meanElementMass(*f.body, m);  // the mass a point the reader gives it
  mirrorFirstJelly(d);
  draftChanged(v, true);
}

// Discard, apply, apply with the suggested dt (discard first: it never moves as the verdict
// arrives and the others' labels change); apply once the change is judged.
void verdictButtons(Viewer& v, bool judged) {
  PanelState& p = panel(v);
  if (button(v, "discard##discard")) {
    discardDraft(v);
    return;
  }
  ImGui::SameLine();
  ImGui::BeginDisabled(!judged);
  const bool unstable = judged && p.verdict->verdict == Verdict::Unstable;
  if (button(v, unstable ? "apply anyway##apply" : "apply##apply")) applyDraft(v, p.draft.run);
  if (judged && p.verdict->verdict != Verdict::Stable && p.verdict->suggested > 0) {
    ImGui::SameLine();
    const std::string label = "apply with dt " + figureText(p.verdict->suggested) + "##apply.dt";
    if (button(v, label.c_str())) {
      RunSettings run = p.draft.run;
      run.dt = p.verdict->suggested;
      applyDraft(v, run);
    }
  }
  ImGui::EndDisabled();
}

}  // namespace

void verdictSection(Viewer& v) {
  PanelState& p = panel(v);
  // A region of fixed height: what follows never moves as verdicts come and go.
  ImGui::BeginChild("verdict", ImVec2(0, 6.5f * ImGui::GetTextLineHeightWithSpacing()));
  const bool current = p.verdict && p.verdictGeneration == p.generation;
  ImGui::TextUnformatted(p.draft.changed ? "Changes, not applied yet:" : "The setup as it runs:");
  if (current) {
    // A line a part ("unstable", "dt ... limit ...", "try dt ..."): wrapped whole, never inside
    // a number.
    ImGui::PushStyleColor(ImGuiCol_Text, verdictColour(p.verdict->verdict));
    std::string rest = p.verdict->text;
    for (std::size_t cut; (cut = rest.find_first_of(":;")) != std::string::npos;
         rest = rest.substr(std::min(cut + 2, rest.size())))
      ImGui::TextUnformatted(rest.substr(0, cut).c_str());
    ImGui::TextWrapped("%s", rest.c_str());
    ImGui::PopStyleColor();
    traceItem(v, "verdict");
    ImGui::TextDisabled("judged in %.2f s%s", p.verdictSeconds,
                        p.verdict->bound ? " (a bound: a large body)" : "");
  } else {
    ImGui::TextDisabled("judging (as jello --check)...");
  }
  if (p.draft.changed) verdictButtons(v, current);
  ImGui::EndChild();
}

void runSection(Viewer& v) {
  if (!ImGui::CollapsingHeader("Run", ImGuiTreeNodeFlags_DefaultOpen)) return;
  PanelState& p = panel(v);
  ImGui::Text("t = %.4f s, step %lld", v.time(), v.simulation.step());
  int integrator = static_cast<int>(p.draft.run.integrator);
  ImGui::PushItemWidth(140);
  if (ImGui::Combo(
          "integrator##run.integrator", &integrator,
          [](void*, int i, const char** name) {
            *name = integratorName(static_cast<Integrator>(i));
            return true;
          },
          nullptr, kIntegratorCount)) {
    p.draft.run.integrator = static_cast<Integrator>(integrator);
    draftChanged(v, false);
  }
  traceItem(v, "run.integrator");
  if (numberField(v, "dt, s##run.dt", &p.draft.run.dt, 0, kLargestSceneNumber, true))
    draftChanged(v, false);
  int n = v.n;
  if (integerField(v, "steps a frame##run.n", &n, 1, kMostStepsPerFrame)) {
    v.n = n;
    p.draft.run.n = n;
    recountRun(v);
  }
  ImGui::PopItemWidth();
  bool paused = v.paused;
  if (checkbox(v, "paused (p)##run.paused", &paused)) togglePause(v);
  ImGui::SameLine();
  bool realTime = v.realTime;
  if (checkbox(v, "real time (r)##run.realtime", &realTime)) toggleRealTime(v);
  ImGui::SameLine();
  ImGui::BeginDisabled(!v.paused || v.diverged);
  if (button(v, "step a frame##run.step")) stepFrame(v);
  ImGui::EndDisabled();
}

void jellySection(Viewer& v) {
  if (!ImGui::CollapsingHeader("Jelly", ImGuiTreeNodeFlags_DefaultOpen)) return;
  PanelState& p = panel(v);
  Draft& d = p.draft;
  const int jellies = std::max<int>(1, static_cast<int>(d.scene.jellies.size()));
  if (jellies > 1) {
    int shown = p.jelly + 1;
    const std::string of = "%d of " + std::to_string(jellies);
    if (ImGui::SliderInt("jelly##jelly.which", &shown, 1, jellies, of.c_str())) p.jelly = shown - 1;
    traceItem(v, "jelly.which");
  }
  p.jelly = std::clamp(p.jelly, 0, jellies - 1);
  JellyFields f = jellyFields(d, p.jelly);
  ImGui::Text("%s, %s", f.body->what.c_str(),
              f.material->elements()
                  ? (std::string(materialInfo(f.material->kind).name) + " elements").c_str()
                  : "springs");
  ImGui::PushItemWidth(120);
  if (f.material->elements())
    elementFields(v, d, f);
  else
    springFields(v, d, f);
  ImGui::PopItemWidth();
}

void contactSection(Viewer& v) {
  if (!ImGui::CollapsingHeader("Contact")) return;
  Draft& d = panel(v).draft;
  ImGui::PushItemWidth(120);
  bool changed =
      numberField(v, "stiffness, N/m##contact.k", &d.world.kCollision, 0, kLargestSceneNumber);
  changed |=
      numberField(v, "damping, N s/m##contact.d", &d.world.dCollision, 0, kLargestSceneNumber);
  ImGui::TextDisabled("the course's walls and plane, and between jellies");
  if (d.scene.bodyContact) {
    BodyContactSpec& c = *d.scene.bodyContact;
    c.spring = {d.world.kCollision, d.world.dCollision};  // the reader's: [contact]'s spring
    changed |= frictionFields(v, "contact.", &c.friction, true);
  }
  ImGui::PopItemWidth();
  if (changed) draftChanged(v, true);
}

void viewSection(Viewer& v) {
  if (!ImGui::CollapsingHeader("View")) return;
  int colouring = static_cast<int>(v.draw.colouring);
  ImGui::PushItemWidth(140);
  if (ImGui::Combo(
          "colouring (c)##view.colouring", &colouring,
          [](void*, int i, const char** name) {
            *name = colouringName(static_cast<Colouring>(i));
            return true;
          },
          nullptr, kColouringKinds)) {
    if (static_cast<Colouring>(colouring) == Colouring::Stress && !v.model.forces.elements)
      v.say("stress colours a jelly of finite elements: this one is made of springs");
    else
      v.draw.colouring = static_cast<Colouring>(colouring), v.draw.colourScale = 0;
  }
  traceItem(v, "view.colouring");
  checkbox(v, "wireframe (v)##view.wireframe", &v.draw.wireframe);
  checkbox(v, "structural (s)##view.structural", &v.draw.structural);
  ImGui::SameLine();
  checkbox(v, "shear (h)##view.shear", &v.draw.shear);
  ImGui::SameLine();
  checkbox(v, "bend (b)##view.bend", &v.draw.bend);
  const double lowest = kMinCameraDistance, farthest = kMaxCameraDistance;
  float azimuth = static_cast<float>(v.camera.phi * 180 / kPi);
  float elevation = static_cast<float>(v.camera.theta * 180 / kPi);
  if (ImGui::SliderFloat("azimuth##view.azimuth", &azimuth, -180, 180, "%.0f deg"))
    v.camera.phi = azimuth * kPi / 180;
  const float highest = static_cast<float>(kMaxElevation * 180 / kPi);
  if (ImGui::SliderFloat("elevation##view.elevation", &elevation, -highest, highest, "%.0f deg"))
    v.camera.theta = elevation * kPi / 180;
  ImGui::SliderScalar("distance, m##view.distance", ImGuiDataType_Double, &v.camera.radius, &lowest,
                      &farthest, "%.2f");
  if (button(v, "reset the camera (e)##view.reset"))
    v.camera = cameraFor(v.model, v.pictures.camera);
  ImGui::SliderFloat3("light##view.light", v.draw.light.data(), -1, 1, "%.2f");
  ImGui::PopItemWidth();
}

void saveSection(Viewer& v) {
  if (!ImGui::CollapsingHeader("Save as", ImGuiTreeNodeFlags_DefaultOpen)) return;
  PanelState& p = panel(v);
  ImGui::PushItemWidth(220);
  ImGui::InputText("scene##save.name", p.saveName, sizeof p.saveName);
  traceItem(v, "save.name");
  ImGui::PopItemWidth();
  checkbox(v, "replace files##save.replace", &p.replace);
  ImGui::SameLine();
  if (!button(v, "save as##save")) return;
  if (p.saveName[0] == '\0') {
    v.say("give the scene's name first (NAME.toml)");
    return;
  }
  const RunSettings run{v.simulation.integrator(), v.simulation.dt(), v.n};
  try {
    writeScene(p.saveName, v.model.world, run, v.state(), p.replace);
    const SavedSceneFiles files = savedSceneFiles(p.saveName, v.model.world.scene != nullptr);
    v.say(textf("saved %s (with %s%s%s beside it) at step %lld%s", files.scene.c_str(),
                files.world.c_str(), files.state.empty() ? "" : " and ", files.state.c_str(),
                v.simulation.step(),
                p.draft.changed ? "; the changes not applied are not in it" : ""));
  } catch (const std::exception& e) {
    const std::string why = e.what();
    const bool exists = why.find("already exists") != std::string::npos;
    v.say(why + (exists ? " (tick \"replace files\" to replace it)" : ""));
  }
}

}  // namespace jello
