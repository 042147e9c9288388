// checks.cpp: the properties the fuzzers check. Built into the fuzz targets (clang, libFuzzer,
// ASan, UBSan) and into the test suite.

#include "checks.h"

#include <sys/mman.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string_view>

#include "app/commandline.h"
#include "app/worldbuilder.h"
#include "core/exitstatus.h"
#include "io/scenereader.h"
#include "model/scenespec.h"
#include "model/world.h"
#include "solver/physics.h"

namespace jello::fuzz {

namespace {

[[noreturn]] void failed(const char* what, const std::string& detail) {
  std::fprintf(stderr, "fuzz check failed: %s: %s\n", what, detail.c_str());
  std::abort();
}

bool sameBits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() &&
         (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
}

bool sameWorld(const WorldFile& a, const WorldFile& b) {
  const World &x = a.world, &y = b.world;
  auto same = [](double p, double q) { return std::memcmp(&p, &q, sizeof p) == 0; };
  return a.run.integrator == b.run.integrator && same(a.run.dt, b.run.dt) && a.run.n == b.run.n &&
         same(x.kElastic, y.kElastic) && same(x.dElastic, y.dElastic) &&
         same(x.kCollision, y.kCollision) && same(x.dCollision, y.dCollision) &&
         same(x.mass, y.mass) && x.hasPlane == y.hasPlane && same(x.plane.a, y.plane.a) &&
         same(x.plane.b, y.plane.b) && same(x.plane.c, y.plane.c) && same(x.plane.d, y.plane.d) &&
         x.field.resolution == y.field.resolution && sameBits(x.field.forces, y.field.forces) &&
         sameBits(a.state.y, b.state.y);
}

// The outcome of reading: the world, or the error's message.
struct Outcome {
  bool accepted = false;
  WorldFile world;
  std::string error;
};

template <class Read>
Outcome outcomeOf(Read read) {
  Outcome o;
  try {
    o.world = read();
    o.accepted = true;
  } catch (const InputError& e) {
    o.error = e.what();
    if (o.error.empty() || o.error.find('\n') != std::string::npos)
      failed("error message", o.error);
  }
  return o;
}

}  // namespace

void checkWorldText(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  // The same bytes as a file: a memfd, read through its /proc path like any file.
  const int fd = ::memfd_create("fuzzed-world", MFD_CLOEXEC);
  if (fd < 0) failed("memfd_create", std::strerror(errno));
  for (std::size_t done = 0; done < size;) {
    ssize_t wrote = ::write(fd, data + done, size - done);
    if (wrote <= 0) failed("write", std::strerror(errno));
    done += static_cast<std::size_t>(wrote);
  }
  const std::string path = "/proc/self/fd/" + std::to_string(fd);
  Outcome fromMemory = outcomeOf([&] { return parseWorld(text, path); });
  Outcome fromFile = outcomeOf([&] { return readWorldFile(path); });
  ::close(fd);
  if (fromMemory.accepted != fromFile.accepted || fromMemory.error != fromFile.error) {
    failed("memory and file disagree", fromMemory.error + " | " + fromFile.error);
  }
  if (fromMemory.accepted) {
    if (!sameWorld(fromMemory.world, fromFile.world))
      failed("memory and file disagree", "different worlds");
    // createWorld's judge of a world in memory must pass every world the reader accepts.
    if (auto problem = findWorldProblem(fromMemory.world)) {
      failed("an accepted world has a problem", problem->what);
    }
    const std::string written = formatWorld(fromMemory.world);
    Outcome again = outcomeOf([&] { return parseWorld(written, "round trip"); });
    if (!again.accepted) failed("a written world is refused", again.error);
    if (!sameWorld(fromMemory.world, again.world))
      failed("round trip", "the world read back differs");
  }
}

void checkFieldExpression(const std::uint8_t* data, std::size_t size) {
  constexpr int kResolution = 3;  // 27 nodes: enough to evaluate everywhere, fast
  FieldRecipe recipe;
  recipe.source = FieldRecipe::Source::Expression;
  recipe.resolution = kResolution;
  recipe.expression.assign(reinterpret_cast<const char*>(data), size);
  try {
    ForceField field = buildField(recipe);
    if (field.resolution != kResolution ||
        field.forces.size() != 3u * kResolution * kResolution * kResolution) {
      failed("field size", recipe.expression);
    }
    for (double f : field.forces)
      if (!std::isfinite(f)) failed("a non-finite force was accepted", recipe.expression);
  } catch (const InputError& e) {
    const std::string message = e.what();
    if (message.empty()) failed("empty error message", recipe.expression);
  }
}

namespace {

constexpr std::size_t kMostArguments = 64;

// Every rule of the options that a parse that goes on must keep.
void checkCommand(const JelloCommand& c) {
  const RunOptions& run = c.run;
  auto positive = [](double x) { return std::isfinite(x) && x > 0; };
  if (run.dt && !positive(*run.dt)) failed("--dt", std::to_string(*run.dt));
  if (run.time && !positive(*run.time)) failed("--time", std::to_string(*run.time));
  if (run.steps && *run.steps < 0) failed("--steps", std::to_string(*run.steps));
  if (run.n && *run.n < 1) failed("--n", std::to_string(*run.n));
  if (!positive(run.tolerances.rtol) || !positive(run.tolerances.atol)) failed("--rtol/--atol", "");
  if (run.dumpPath && run.dumpPath->empty()) failed("--dump", "empty");
  if (run.worldPath.empty()) failed("WORLD", "empty");
  const PictureOptions& p = c.pictures;
  if (p.width < kMinPictureSize || p.width > kMaxPictureSize || p.height < kMinPictureSize ||
      p.height > kMaxPictureSize)
    failed("--size", std::to_string(p.width) + "x" + std::to_string(p.height));
  if (p.maxFrames < 1 || p.maxFrames > kMaxFrames)
    failed("--max-frames", std::to_string(p.maxFrames));
  if (c.framesGiven && p.framesDir.empty()) failed("--frames", "empty");
  if (!p.exportDir.empty() && c.mode != JelloCommand::Mode::Run)
    failed("--export", "with --check, --report or --bench");
  if (c.mode == JelloCommand::Mode::Report &&
      (c.report.dir.empty() || !positive(c.report.time) || !positive(c.report.visualTolerance)))
    failed("--report", c.report.dir);
  if (c.mode == JelloCommand::Mode::Map && (c.mapDir.empty() || !positive(c.mapTime)))
    failed("--map", c.mapDir);
  if (c.json && c.mode != JelloCommand::Mode::Check) failed("--json", "without --check");
}

}  // namespace

void checkCommandLine(const std::uint8_t* data, std::size_t size) {
  std::vector<std::string> args = {"jello"};
  std::string current;
  for (std::size_t i = 0; i < size && args.size() < kMostArguments; ++i) {
    if (data[i] != 0) {
      current += static_cast<char>(data[i]);
      continue;
    }
    args.push_back(current);
    current.clear();
  }
  if (!current.empty() && args.size() < kMostArguments) args.push_back(current);
  std::vector<const char*> argv;
  for (const std::string& a : args) argv.push_back(a.c_str());
  JelloCommand command;
  ParsedCommand parsed;
  try {
    parsed = parseJelloCommandLine(static_cast<int>(argv.size()), argv.data(), &command);
  } catch (const std::exception& e) {
    failed("an exception escaped the parse", e.what());
  }
  if (parsed.goOn)
    checkCommand(command);
  else if (!parsed.outcome.ok() && parsed.outcome.status != Ending::Failed)
    failed("the parse's outcome", parsed.outcome.message);
  else if (!parsed.outcome.ok() && parsed.outcome.message.empty())
    failed("a refusal that says why", parsed.outcome.message);
  // The message may quote what the user typed, newlines and all: main prints it through
  // printError, which shows every control character as \xNN, so it reaches the user as one line.
}

// An accepted scene keeps the reader's promises: the world is one formatWorld can write, every
// obstacle can be simulated, pins are sorted, distinct points, and the forces are finite.
void checkSceneText(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const Outcome o = outcomeOf([&] { return parseScene(text, "fuzzed.toml", ""); });
  if (!o.accepted) return;
  const WorldFile& file = o.world;
  if (auto problem = findWorldProblem(file))
    failed("an accepted scene has a problem", problem->what);
  const SceneSpec& spec = *file.world.scene;
  for (const Obstacle& ob : spec.obstacles) {
    const Friction& f = ob.friction;
    if (!(ob.spring.k >= 0 && ob.spring.d >= 0 && f.muDynamic >= 0 && f.muDynamic <= f.muStatic &&
          f.speed > 0))
      failed("an accepted obstacle", obstacleText(ob));
    if (ob.shape == ObstacleShape::Sphere && !(ob.radius > 0)) failed("a sphere", obstacleText(ob));
  }
  const int points = file.state.points();
  for (std::size_t i = 0; i < spec.pinned.size(); ++i)
    if (spec.pinned[i] < 0 || spec.pinned[i] >= points ||
        (i > 0 && spec.pinned[i] <= spec.pinned[i - 1]))
      failed("pins", "not sorted, distinct points");
  // Several jellies: each with a mass above 0, and the joined body's parts cover every point.
  for (const JellySpec& jelly : spec.jellies)
    if (!(jelly.mass > 0)) failed("a jelly's mass", "not above 0");
  if (!spec.jellies.empty() &&
      (spec.body->parts.size() != spec.jellies.size() || spec.body->partFirst.back() != points))
    failed("several jellies", "their parts are not the body's points");
  const Model model = makeModel(file.world, file.state);
  if (model.points() != points) failed("a scene's model", "not as many points as its state");
  std::vector<double> force(3 * std::size_t(points));
  computeForces(model, file.state.p(), file.state.v(), force.data());
  for (double f : force)
    if (std::isnan(f)) failed("a scene's forces", "not a number");
}

}  // namespace jello::fuzz
