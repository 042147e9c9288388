// Pictures: the off-screen renderer, JPEG files, frame sequences, and --frames from the
// command line (README: Running, The viewer). Built only where GL and OSMesa are.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cmath>
#include <fstream>

#include "app/export.h"
#include "graphics/frames.h"
#include "graphics/image.h"
#include "graphics/offscreen.h"
#include "io/scenereader.h"
#include "solver/simulation.h"
#include "test_support.h"

namespace jello {
namespace {

using test::centroid;
using test::dataPath;

struct Rgb {
  int r, g, b;
};

Rgb pixel(const Image& image, int x, int y) {
  const std::uint8_t* p = &image.rgb[(static_cast<std::size_t>(y) * image.width + x) * 3];
  return {p[0], p[1], p[2]};
}

bool isBackground(Rgb c) {
  return std::abs(c.r - 128) <= 6 && std::abs(c.g - 128) <= 6 && std::abs(c.b - 128) <= 6;
}

double meanAbsoluteDifference(const Image& a, const Image& b) {
  EXPECT_EQ(a.rgb.size(), b.rgb.size());
  double sum = 0;
  for (std::size_t i = 0; i < a.rgb.size() && i < b.rgb.size(); ++i)
    sum += std::abs(int(a.rgb[i]) - int(b.rgb[i]));
  return sum / a.rgb.size();
}

// Where a pinhole camera on the sphere (README, The viewer: looking at the origin, camera.up up)
// puts a point, in pixels from the top-left; computed here from first principles, not through GL.
void projectToPixel(const Camera& camera, Vec3 point, int width, int height, double* x, double* y) {
  double len;
  Vec3 eye = camera.eye();
  Vec3 forward = direction(-eye, &len);
  Vec3 right = direction(cross(forward, camera.up), &len);
  Vec3 up = cross(right, forward);
  Vec3 d = point - eye;
  double f = 1 / std::tan(kFieldOfView * kPi / 360);
  double aspect = double(width) / height;
  double ndcX = f / aspect * dot(d, right) / dot(d, forward);
  double ndcY = f * dot(d, up) / dot(d, forward);
  *x = (ndcX + 1) / 2 * width;
  *y = (1 - ndcY) / 2 * height;
}

TEST(Offscreen, FrameOfAKnownStateIsAGreyPictureWithTheCubeWhereTheCameraPutsIt) {
  WorldFile f = readWorldFile(dataPath("still.w"));
  Model model = makeModel(f.world, f.state);
  OffscreenRenderer renderer(320, 240);
  std::string dir = test::makeTempDir();
  writeJpeg(dir + "/frame.jpg", renderer.render(model, f.state, Camera{}, DrawOptions{}));
  Image image = readJpeg(dir + "/frame.jpg");
  test::removeTree(dir);
  ASSERT_EQ(image.width, 320);
  ASSERT_EQ(image.height, 240);
  EXPECT_TRUE(isBackground(pixel(image, 3, 236)));
  EXPECT_TRUE(isBackground(pixel(image, 316, 120)));

  for (Camera camera : {Camera{}, Camera{8, 0.3, -2.0}, Camera{5, -0.4, 2.5}}) {
    Image view = renderer.render(model, f.state, camera, DrawOptions{});
    double x, y;
    projectToPixel(camera, centroid(f.state), 320, 240, &x, &y);
    ASSERT_TRUE(x >= 0 && x < 320 && y >= 0 && y < 240) << x << "," << y;
    Rgb c = pixel(view, int(x), int(y));
    EXPECT_FALSE(isBackground(c)) << "camera phi=" << camera.phi << ": " << c.r << " " << c.g << " "
                                  << c.b;
    EXPECT_GT(c.r, c.g + 40) << "the jelly is red";
    // A point well outside the cube's image is background.
    projectToPixel(camera, centroid(f.state) + Vec3{0, 0, 1.5}, 320, 240, &x, &y);
    EXPECT_TRUE(isBackground(pixel(view, int(x), int(y)))) << "camera phi=" << camera.phi;
  }
}

TEST(Offscreen, ColouringsAndSpringsChangeThePicture) {
  WorldFile f = readWorldFile(dataPath("jello.w"));  // starts stretched
  Model model = makeModel(f.world, f.state);
  OffscreenRenderer renderer(320, 240);
  Image plain = renderer.render(model, f.state, Camera{}, DrawOptions{});
  DrawOptions options;
  for (Colouring colouring : {Colouring::Strain, Colouring::Force}) {
    options.colouring = colouring;
    EXPECT_GT(meanAbsoluteDifference(plain, renderer.render(model, f.state, Camera{}, options)),
              0.5)
        << colouringName(colouring);
  }
  options = DrawOptions{};
  options.structural = options.shear = options.bend = true;
  options.wireframe = true;
  EXPECT_GT(meanAbsoluteDifference(plain, renderer.render(model, f.state, Camera{}, options)), 0.5);
}

// The share of the cube's picture (a square around its centre) drawn in `colour`.
double shareOfColour(const Image& image, const Camera& camera, const State& state, Rgb colour) {
  double cx, cy;
  projectToPixel(camera, centroid(state), image.width, image.height, &cx, &cy);
  const int half = image.height / 10;
  int cube = 0, coloured = 0;
  for (int y = int(cy) - half; y <= int(cy) + half; ++y)
    for (int x = int(cx) - half; x <= int(cx) + half; ++x) {
      Rgb c = pixel(image, x, y);
      if (isBackground(c)) continue;
      ++cube;
      coloured += std::abs(c.r - colour.r) < 40 && std::abs(c.g - colour.g) < 40 &&
                  std::abs(c.b - colour.b) < 40;
    }
  return cube > 0 ? double(coloured) / cube : 0;
}

TEST(Offscreen, SpringLinesOnTheSurfaceAreDrawnWholeNotHalfHiddenInIt) {
  WorldFile f = readWorldFile(dataPath("still.w"));
  Model model = makeModel(f.world, f.state);
  OffscreenRenderer renderer(640, 480);
  DrawOptions options;
  options.shear = true;
  const Rgb shearYellow{242, 217, 51};
  // Whole, the face diagonals cover about 40% of the middle of the cube's picture; sharing the
  // surface's depth, half of them were lost to it (z-fighting: 21%).
  const double share = shareOfColour(renderer.render(model, f.state, Camera{}, options), Camera{},
                                     f.state, shearYellow);
  EXPECT_GT(share, 0.3);
}

TEST(Offscreen, TheSpringsLegendShowsEachKindsColourAtTheTopRight) {
  WorldFile f = readWorldFile(dataPath("still.w"));
  Model model = makeModel(f.world, f.state);
  OffscreenRenderer renderer(640, 480);
  DrawOptions options;
  options.structural = options.bend = true;
  const Image image = renderer.render(model, f.state, Camera{}, options);
  const LegendLayout legend = layoutLegends(640, 480, 2, false);
  ASSERT_FALSE(legend.springs.empty());
  const int swatchY = legend.springs.y + kGlyphHeight * legend.scale / 2;
  const int lineHeight = kLineAdvance * legend.scale;
  const Rgb structural = pixel(image, legend.springs.x + 2, swatchY);
  const Rgb bend = pixel(image, legend.springs.x + 2, swatchY + lineHeight);
  EXPECT_NEAR(structural.r, 51, 30);
  EXPECT_NEAR(structural.g, 230, 30);
  EXPECT_NEAR(bend.r, 217, 30);
  EXPECT_NEAR(bend.g, 77, 30);
  EXPECT_TRUE(isBackground(pixel(renderer.render(model, f.state, Camera{}, DrawOptions{}),
                                 legend.springs.x + 2, swatchY)));
}

TEST(Offscreen, AHeldColourScaleIsTheLegendsWhateverTheState) {
  WorldFile f = readWorldFile(dataPath("jello.w"));  // starts stretched
  Model model = makeModel(f.world, f.state);
  OffscreenRenderer renderer(320, 240);
  DrawOptions options;
  options.colouring = Colouring::Strain;
  const double fitted = fittedColourScale(model, f.state, Colouring::Strain);
  ASSERT_GT(fitted, 0);
  EXPECT_EQ(fittedColourScale(model, f.state, Colouring::Plain), 0);
  const Image fit = renderer.render(model, f.state, Camera{}, options);
  options.colourScale = fitted;
  EXPECT_EQ(meanAbsoluteDifference(fit, renderer.render(model, f.state, Camera{}, options)), 0);
  options.colourScale = 100 * fitted;  // every strain near zero: paler, another legend
  EXPECT_GT(meanAbsoluteDifference(fit, renderer.render(model, f.state, Camera{}, options)), 0.2);
}

WorldFile sceneText(const std::string& text) {
  return parseScene(text, "test.toml", std::string(JELLO_SOURCE_DIR));
}

Rgb pixelAt(const Image& image, const Camera& camera, Vec3 point) {
  double x, y;
  projectToPixel(camera, point, image.width, image.height, &x, &y);
  EXPECT_TRUE(x >= 0 && x < image.width && y >= 0 && y < image.height) << x << "," << y;
  return pixel(image, std::clamp(int(x), 0, image.width - 1),
               std::clamp(int(y), 0, image.height - 1));
}

// Whether some pixel within 3 of where `point` is drawn passes `test`.
template <typename Test>
bool nearPixel(const Image& image, const Camera& camera, Vec3 point, Test test) {
  double cx, cy;
  projectToPixel(camera, point, image.width, image.height, &cx, &cy);
  for (int y = int(cy) - 3; y <= int(cy) + 3; ++y)
    for (int x = int(cx) - 3; x <= int(cx) + 3; ++x)
      if (x >= 0 && y >= 0 && x < image.width && y < image.height && test(pixel(image, x, y)))
        return true;
  return false;
}

// A scene's ball and box (solid teal), its floor (translucent sand), its pinned corner (a dark
// ball) and its bounding box of half side 1.5 (white lines) are each where the camera puts them;
// the course box's corner is not drawn.
TEST(SceneDrawing, ObstaclesPinsFloorAndTheScenesOwnBoxAreWhereTheCameraPutsThem) {
  const WorldFile f = sceneText(
      "[bounds]\nlower = [-1.5, -1.5, -1.5]\nupper = [1.5, 1.5, 1.5]\n[[sphere]]\ncentre = [0, 0, "
      "-1.1]\nradius = 0.35\n[[box]]\nlower = [0.7, -1.4, -1.4]\nupper = [1.3, -0.8, -0.8]\n"
      "[[plane]]\npoint = [0, 0, -1.45]\nnormal = [0, 0, 1]\n[[pin]]\ni = [7, 7]\nj = [0, "
      "0]\nk = [7, 7]\n");
  const Model model = makeModel(f.world, f.state);
  OffscreenRenderer renderer(640, 480);
  const Camera camera = cameraFor(model);
  const Image image = renderer.render(model, f.state, camera, DrawOptions{});
  auto teal = [](Rgb c) { return c.g > c.r + 40 && c.b > c.r + 40; };
  EXPECT_TRUE(teal(pixelAt(image, camera, {0, 0, -1.1})));
  EXPECT_TRUE(teal(pixelAt(image, camera, {1.0, -1.1, -0.8})));  // the box's top face
  const Rgb pin = pixelAt(image, camera, load(f.state.p(), pointIndex(7, 0, 7)));
  EXPECT_LT(std::max({pin.r, pin.g, pin.b}), 60) << pin.r << " " << pin.g << " " << pin.b;
  const Rgb floor = pixelAt(image, camera, {-1.2, 1.2, -1.45});
  EXPECT_FALSE(isBackground(floor));
  EXPECT_GT(floor.r, floor.b + 20) << "sand, not grey";
  auto white = [](Rgb c) { return std::min({c.r, c.g, c.b}) > 200; };
  EXPECT_TRUE(nearPixel(image, camera, {1.5, 1.5, 1.5}, white));
  EXPECT_TRUE(nearPixel(image, camera, {-1.5, 1.5, 1.5}, white));
  EXPECT_FALSE(nearPixel(image, camera, {2, 2, 2}, white));
  EXPECT_FALSE(nearPixel(image, camera, {-2, 2, 2}, white));
}

// A scene that adds nothing to a course world draws the course world's picture, pixel for pixel;
// one without a bounding box draws none.
TEST(SceneDrawing, ASceneAddingNothingDrawsTheCourseWorldsPicture) {
  const WorldFile course = readWorldFile(std::string(JELLO_SOURCE_DIR) + "/world/rotate.w");
  const WorldFile through = sceneText("world = \"world/rotate.w\"\n");
  const Model a = makeModel(course.world, course.state),
              b = makeModel(through.world, through.state);
  OffscreenRenderer renderer(320, 240);
  const Image courseImage = renderer.render(a, course.state, Camera{}, DrawOptions{});
  EXPECT_EQ(meanAbsoluteDifference(courseImage,
                                   renderer.render(b, through.state, cameraFor(b), DrawOptions{})),
            0);
  const WorldFile open = sceneText("world = \"world/rotate.w\"\n[bounds]\npresent = false\n");
  const Model c = makeModel(open.world, open.state);
  const Image openImage = renderer.render(c, open.state, cameraFor(c), DrawOptions{});
  auto white = [](Rgb p) { return std::min({p.r, p.g, p.b}) > 200; };
  EXPECT_TRUE(nearPixel(courseImage, Camera{}, {2, 2, -2}, white));
  EXPECT_FALSE(nearPixel(openImage, Camera{}, {2, 2, -2}, white));
}

// The camera: the course's eye to the bit with +z up; pushes horizontal as seen; up against a
// scene's gravity; a large box seen whole; --camera's angles and distance.
TEST(Camera, UpIsAgainstTheScenesGravityAndPushesAreHorizontalAsSeen) {
  const Camera course;
  const double r = 6, a = kPi / 6;
  const Vec3 eye = course.eye();
  EXPECT_EQ(eye.x, r * std::cos(a) * std::cos(a));
  EXPECT_EQ(eye.y, r * std::sin(a) * std::cos(a));
  EXPECT_EQ(eye.z, r * std::sin(a));
  EXPECT_LT(length(course.away() - Vec3{-std::cos(a), -std::sin(a), 0}), 1e-15);
  EXPECT_LT(length(course.right() - Vec3{-std::sin(a), std::cos(a), 0}), 1e-15);

  const WorldFile slope =
      readSceneFile(std::string(JELLO_SOURCE_DIR) + "/scenes/slope-slides.toml");
  const Model slopeModel = makeModel(slope.world, slope.state);
  const Camera tilted = cameraFor(slopeModel);
  const double tilt = 25 * kPi / 180;  // the scene's gravity, from the vertical
  EXPECT_LT(length(tilted.up - Vec3{-std::sin(tilt), 0, std::cos(tilt)}), 1e-3);
  EXPECT_LT(std::fabs(dot(tilted.away(), tilted.up)), 1e-15);
  EXPECT_LT(std::fabs(dot(tilted.right(), tilted.up)), 1e-15);
  EXPECT_NEAR(dot(tilted.eye(), tilted.up), r * std::sin(a), 1e-12);
  EXPECT_NEAR(length(tilted.eye()), r, 1e-12);

  const WorldFile large = sceneText("[bounds]\nlower = [-4, -4, -4]\nupper = [4, 4, 4]\n");
  EXPECT_NEAR(cameraFor(makeModel(large.world, large.state)).radius, 12, 1e-12);
  const Camera asked = cameraFor(slopeModel, CameraRequest{90, 0, 3});
  EXPECT_LT(length(asked.eye() - 3 * tilted.horizontalAxis(1)), 1e-12);
}

// Settled on the scenes' slope and seen from the side, the jelly's bottom edge is green where it
// sticks (slope-friction) and orange where it slides (slope-slides), and the legend says which.
TEST(SceneDrawing, TheFrictionColouringShowsStickingGreenAndSlidingOrange) {
  auto render = [](const char* name, const Image** out, OffscreenRenderer* renderer) {
    const WorldFile f = readSceneFile(std::string(JELLO_SOURCE_DIR) + "/scenes/" + name);
    const Model model = makeModel(f.world, f.state);
    Simulation run(model, f.state, f.run.integrator, f.run.dt);
    EXPECT_TRUE(run.advanceTo(0.5).ran());
    DrawOptions options;
    options.colouring = Colouring::Friction;
    *out = &renderer->render(model, run.state(), cameraFor(model, CameraRequest{-90, 8, 3.5}),
                             options);
  };
  const LegendLayout legend = layoutLegends(640, 480, 0, true);
  auto count = [&](const Image& image, auto test) {
    int n = 0;
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < legend.colours.x; ++x) n += test(pixel(image, x, y));
    return n;
  };
  auto green = [](Rgb c) { return c.g > c.r + 50 && c.g > c.b + 50; };
  auto orange = [](Rgb c) { return c.r > 180 && c.g < c.r - 50 && c.b < 110; };
  OffscreenRenderer renderer(640, 480);
  const Image* image = nullptr;
  render("slope-friction.toml", &image, &renderer);
  const int stickingGreen = count(*image, green), stickingOrange = count(*image, orange);
  const Rgb firstSwatch =
      pixel(*image, legend.bar.x + 2, legend.bar.bottom() - 3 * kLineAdvance * legend.scale + 2);
  EXPECT_TRUE(green(firstSwatch)) << firstSwatch.r << " " << firstSwatch.g << " " << firstSwatch.b;
  render("slope-slides.toml", &image, &renderer);
  const int slidingGreen = count(*image, green), slidingOrange = count(*image, orange);
  std::printf("sticking: %d green, %d orange pixels; sliding: %d green, %d orange\n", stickingGreen,
              stickingOrange, slidingGreen, slidingOrange);
  EXPECT_GT(stickingGreen, 100);
  EXPECT_EQ(stickingOrange, 0);
  EXPECT_GT(slidingOrange, 50);
  EXPECT_EQ(slidingGreen, 0);
}

// A jelly of elements of 5 x 5 x 5 points 5 cm apart, in a box about it.
constexpr const char* kElementScene =
    "dt = 0.0001\n[bounds]\nlower = [-0.2, -0.2, -0.2]\nupper = [0.2, 0.2, 0.3]\n[jelly]\n"
    "shape = \"lattice\"\nsize = [5, 5, 5]\nspacing = 0.05\nmaterial = \"neohookean\"\n"
    "youngs_modulus = 1e4\npoisson_ratio = 0.45\ndensity = 1000\n";

Vec3 meanPosition(const State& state) {
  Vec3 sum;
  for (int q = 0; q < state.points(); ++q) sum += load(state.p(), q, state.points());
  return (1.0 / state.points()) * sum;
}

// `state` stretched by `factor` along x about its mean: every element's deformation is
// diag(factor, 1, 1), its principal strain factor - 1.
State stretchedAlongX(const State& state, double factor) {
  State out = state;
  const int n = state.points();
  const Vec3 centre = meanPosition(state);
  for (int q = 0; q < n; ++q) {
    const Vec3 d = load(state.p(), q, n) - centre;
    store(out.p(), q, n, centre + Vec3{factor * d.x, d.y, d.z});
  }
  return out;
}

// A jelly of elements has no springs: its strain is its elements', signed (red stretched, blue
// compressed), and the legend's scale fits it (not 0 / 0 at every point).
TEST(SceneDrawing, TheStrainOfAJellyOfElementsIsItsElementsPrincipalStrain) {
  const WorldFile f = sceneText(kElementScene);
  const Model model = makeModel(f.world, f.state);
  ASSERT_NE(model.forces.elements, nullptr);
  ASSERT_TRUE(model.springs().empty());
  const State stretched = stretchedAlongX(f.state, 1.05);
  const State squeezed = stretchedAlongX(f.state, 0.95);
  EXPECT_NEAR(fittedColourScale(model, stretched, Colouring::Strain), 0.05, 1e-12);
  EXPECT_NEAR(fittedColourScale(model, squeezed, Colouring::Strain), 0.05, 1e-12);
  EXPECT_EQ(fittedColourScale(model, f.state, Colouring::Strain), 1e-3) << "at rest: the least";
  OffscreenRenderer renderer(320, 240);
  const Camera camera = cameraFor(model);
  DrawOptions options;
  options.colouring = Colouring::Strain;
  const Rgb red =
      pixelAt(renderer.render(model, stretched, camera, options), camera, meanPosition(stretched));
  EXPECT_GT(red.r, red.b + 60) << red.r << " " << red.g << " " << red.b;
  const Rgb blue =
      pixelAt(renderer.render(model, squeezed, camera, options), camera, meanPosition(squeezed));
  EXPECT_GT(blue.b, blue.r + 60) << blue.r << " " << blue.g << " " << blue.b;
}

// The stress colouring shows the elements' von Mises stress, in Pa; a world of springs has none.
TEST(SceneDrawing, TheStressColouringShowsTheElementsVonMisesStress) {
  const WorldFile f = sceneText(kElementScene);
  const Model model = makeModel(f.world, f.state);
  const State stretched = stretchedAlongX(f.state, 1.05);
  const double stress = model.forces.elements->vonMises(0, stretched.p());  // every element's
  ASSERT_GT(stress, 100);
  const double scale = fittedColourScale(model, stretched, Colouring::Stress);
  EXPECT_GE(scale, stress);
  EXPECT_LE(scale, 2.5 * stress) << "a round 1, 2 or 5 at least the largest";
  EXPECT_EQ(fittedColourScale(model, f.state, Colouring::Stress), 1) << "Pa: the least";
  OffscreenRenderer renderer(320, 240);
  const Camera camera = cameraFor(model);
  const Image plain = renderer.render(model, stretched, camera, DrawOptions{});
  DrawOptions options;
  options.colouring = Colouring::Stress;
  const Image coloured = renderer.render(model, stretched, camera, options);
  EXPECT_GT(meanAbsoluteDifference(plain, coloured), 0.5);
  EXPECT_STREQ(colouringName(Colouring::Stress), "stress");

  WorldFile springs = readWorldFile(dataPath("jello.w"));  // starts stretched
  const Model springModel = makeModel(springs.world, springs.state);
  EXPECT_EQ(fittedColourScale(springModel, springs.state, Colouring::Stress), 1);
}

TEST(Offscreen, RefusesSizesOutOfRange) {
  EXPECT_THROW(OffscreenRenderer(8, 480), std::runtime_error);
  EXPECT_THROW(OffscreenRenderer(640, 100000), std::runtime_error);
}

TEST(Jpeg, RoundTripKeepsSizeAndPixelsClose) {
  Image image;
  image.width = 64;
  image.height = 48;
  for (int y = 0; y < 48; ++y)
    for (int x = 0; x < 64; ++x)
      image.rgb.insert(image.rgb.end(), {std::uint8_t(x * 4), std::uint8_t(y * 5), 90});
  std::string dir = test::makeTempDir();
  writeJpeg(dir + "/a.jpg", image);
  Image back = readJpeg(dir + "/a.jpg");
  EXPECT_EQ(back.width, 64);
  EXPECT_EQ(back.height, 48);
  EXPECT_LT(meanAbsoluteDifference(image, back), 3);
  EXPECT_THROW(writeJpeg(dir + "/missing/a.jpg", image), std::runtime_error);
  test::writeText(dir + "/not.jpg", "plain text");
  EXPECT_THROW(readJpeg(dir + "/not.jpg"), std::runtime_error);
  test::removeTree(dir);
}

Image tiny(std::uint8_t shade) {
  Image image;
  image.width = image.height = 16;
  image.rgb.assign(16 * 16 * 3, shade);
  return image;
}

TEST(FrameSequence, NumbersFromZeroAndStopsAtTheMost) {
  std::string dir = test::makeTempDir();
  FrameSequence frames(dir + "/a/b/", 3, false);
  for (int i = 0; i < 5; ++i) frames.save(tiny(10));
  EXPECT_EQ(frames.written(), 3);
  EXPECT_TRUE(frames.full());
  EXPECT_EQ(countFrames(dir + "/a/b"), 3);
  for (const char* name : {"0000.jpg", "0001.jpg", "0002.jpg"}) {
    EXPECT_NO_THROW(readJpeg(dir + "/a/b/" + name)) << name;
  }
  test::removeTree(dir);
}

TEST(FrameSequence, NeverOverwritesUnlessAskedAndThenLeavesNoStaleTail) {
  std::string dir = test::makeTempDir();
  {
    FrameSequence first(dir, 5, false);  // a finished run: its claim on the folder ends here
    for (int i = 0; i < 5; ++i) first.save(tiny(200));
  }
  std::string before = test::readText(dir + "/0004.jpg");
  {
    FrameSequence second(dir, 5, false);
    EXPECT_THROW(second.save(tiny(10)), FrameError);
  }
  EXPECT_EQ(test::readText(dir + "/0004.jpg"), before);
  EXPECT_EQ(countFrames(dir), 5);
  {
    FrameSequence third(dir, 2, true);
    third.save(tiny(10));
    third.save(tiny(10));
    EXPECT_EQ(countFrames(dir), 2) << "frames 0002-0004 of the old sequence were left behind";
  }
  EXPECT_LT(readJpeg(dir + "/0000.jpg").rgb[0], 50);
  test::writeText(dir + "/notes.txt", "mine");
  FrameSequence fourth(dir, 2, true);
  fourth.open();
  EXPECT_EQ(test::readText(dir + "/notes.txt"), "mine") << "only frames are replaced";
  test::removeTree(dir);
}

TEST(FrameSequence, NewFoldersAreMadeOnceEachAndNeverShared) {
  std::string dir = test::makeTempDir();
  EXPECT_EQ(makeNewFolder(dir + "/animation", "rotate"), dir + "/animation/rotate-001");
  EXPECT_EQ(makeNewFolder(dir + "/animation", "rotate"), dir + "/animation/rotate-002");
  ::mkdir((dir + "/animation/rotate-003").c_str(), 0777);
  EXPECT_EQ(makeNewFolder(dir + "/animation", "rotate"), dir + "/animation/rotate-004");
  test::removeTree(dir);
}

TEST(CliFrames, HeadlessFramesAreNumberedCappedAndNeverOverwritten) {
  std::string dir = test::makeTempDir();
  std::string frames = dir + "/out frames";
  std::string args = "--headless --steps 30 --fps 0 --max-frames 5 --frames '" + frames + "' '" +
                     dataPath("rotate.w") + "'";
  test::CommandResult r = test::runJello(args);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("5 frames in " + frames + "/"), std::string::npos) << r.out;
  EXPECT_NE(r.err.find("the most --max-frames 5 allows, at 0.004 s of the run's 0.03 s"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(countFrames(frames), 5);
  Image first = readJpeg(frames + "/0000.jpg");
  EXPECT_EQ(first.width, 640);
  EXPECT_EQ(first.height, 480);
  std::string before = test::readText(frames + "/0003.jpg");

  test::CommandResult again = test::runJello(args);
  EXPECT_EQ(again.status, 2);
  EXPECT_NE(again.err.find("--overwrite"), std::string::npos) << again.err;
  EXPECT_EQ(std::count(again.err.begin(), again.err.end(), '\n'), 1) << again.err;
  EXPECT_EQ(again.out, "");
  EXPECT_EQ(test::readText(frames + "/0003.jpg"), before);

  test::CommandResult replaced = test::runJello("--overwrite --size 320x240 " + args);
  EXPECT_EQ(replaced.status, 0) << replaced.err;
  EXPECT_EQ(readJpeg(frames + "/0000.jpg").width, 320);
  test::removeTree(dir);
}

TEST(CliFrames, FramesOfRotateChangeOverTime) {
  std::string dir = test::makeTempDir();
  test::CommandResult r = test::runJello("--headless --n 300 --fps 0 --steps 900 --frames '" + dir +
                                         "' '" + dataPath("rotate.w") + "'");
  ASSERT_EQ(r.status, 0) << r.err;
  ASSERT_EQ(countFrames(dir), 4);  // steps 0, 300, 600, 900
  Image a = readJpeg(dir + "/0000.jpg"), b = readJpeg(dir + "/0001.jpg"),
        c = readJpeg(dir + "/0003.jpg");
  EXPECT_GT(meanAbsoluteDifference(a, b), 0.2);
  EXPECT_GT(meanAbsoluteDifference(b, c), 0.2);
  test::removeTree(dir);
}

TEST(CliFrames, WithoutADisplayItRunsHeadlessIntoANewFolderItNames) {
  std::string dir = test::makeTempDir();
  test::CommandResult r =
      test::runJello("--steps 100 '" + dataPath("rotate.w") + "'", dir, "env -u DISPLAY");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("no display"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("animation/rotate-001"), std::string::npos) << r.err;
  EXPECT_EQ(countFrames(dir + "/animation/rotate-001"), 4);  // steps 0, 34, 67, 100: 30 a second
  test::CommandResult again =
      test::runJello("--steps 100 '" + dataPath("rotate.w") + "'", dir, "env -u DISPLAY");
  EXPECT_EQ(again.status, 0) << again.err;
  EXPECT_EQ(countFrames(dir + "/animation/rotate-002"), 4);
  test::removeTree(dir);
}

bool exists(const std::string& path) {
  struct stat info {};
  return ::stat(path.c_str(), &info) == 0;
}

// Refused input leaves nothing behind: not the new frames folder, nor the animation/ folder
// the run made for it.
TEST(CliFrames, WithoutADisplayARefusedWorldLeavesNoFolderBehind) {
  const std::string dir = test::makeTempDir();
  test::writeText(dir + "/bad.w", "garbage\n");
  test::writeText(dir + "/bad.toml", "dt = \"x\"\n");
  for (const char* input : {"bad.w", "bad.toml"}) {
    const test::CommandResult r =
        test::runJello(std::string("--steps 5 ") + input, dir, "env -u DISPLAY");
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_FALSE(exists(dir + "/animation")) << input << ": " << r.err;
  }
  // An animation/ folder that was there stays, without the refused run's folder in it.
  ASSERT_EQ(::mkdir((dir + "/animation").c_str(), 0777), 0);
  const test::CommandResult r = test::runJello("--steps 5 bad.w", dir, "env -u DISPLAY");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_TRUE(exists(dir + "/animation"));
  EXPECT_FALSE(exists(dir + "/animation/bad-001")) << r.err;
  test::removeTree(dir);
}

TEST(CliFrames, FramesAreSavedBySimulatedTimeAndADefaultRunIsMaxFramesOfThem) {
  std::string dir = test::makeTempDir();
  const std::string world = " '" + dataPath("rotate.w") + "'";
  test::CommandResult r = test::runJello("--headless --time 1 --fps 10 --frames a" + world, dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(countFrames(dir + "/a"), 11);  // 0, 0.1, ..., 1 s
  EXPECT_EQ(r.err, "") << "all saved: nothing to say";
  // No --steps or --time: as long as --max-frames frames take, 10 at 50 a second.
  r = test::runJello("--headless --max-frames 10 --fps 50 --frames b" + world, dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("steps=180 "), std::string::npos) << r.out;
  EXPECT_EQ(countFrames(dir + "/b"), 10);
  EXPECT_EQ(r.err, "");
  test::removeTree(dir);
}

TEST(CliFrames, HittingMaxFramesIsSaidNamingTheOption) {
  std::string dir = test::makeTempDir();
  test::CommandResult r = test::runJello(
      "--headless --time 1 --fps 10 --max-frames 4 --frames f '" + dataPath("rotate.w") + "'", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(countFrames(dir + "/f"), 4);
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  for (const char* part : {"f/: saving stopped at 4 frames", "--max-frames 4",
                           "at 0.3 s of the run's 1 s", "raise --max-frames", "--fps"})
    EXPECT_NE(r.err.find(part), std::string::npos) << part << " missing from: " << r.err;
  test::removeTree(dir);
}

// The meshes of --export are written at the frames' steps and numbered as the frames, in one
// folder shared with them (the names do not clash) or in folders of their own.
TEST(CliFrames, ExportedMeshesAreNamedLikeTheFramesOfTheSameSteps) {
  std::string dir = test::makeTempDir();
  const std::string world = " '" + dataPath("rotate.w") + "'";
  test::CommandResult r =
      test::runJello("--headless --time 0.1 --size 64x48 --frames both --export both" + world, dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("4 frames in both/; 4 meshes (OBJ) in both/"), std::string::npos) << r.out;
  EXPECT_EQ(countFrames(dir + "/both"), 4);
  EXPECT_EQ(countMeshes(dir + "/both"), 4);
  for (const char* name : {"0000.jpg", "0000.obj", "0003.jpg", "0003.obj"}) {
    struct stat info;
    EXPECT_EQ(::stat((dir + "/both/" + name).c_str(), &info), 0) << name;
  }
  r = test::runJello(
      "--headless --time 1 --max-frames 5 --size 64x48 --frames f --export m" + world, dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(countFrames(dir + "/f"), 5);
  EXPECT_EQ(countMeshes(dir + "/m"), 5);
  EXPECT_NE(r.err.find("note: f/ and m/: saving stopped at 5 frames"), std::string::npos) << r.err;
  // Without a display, the frames go into a folder jello names; the meshes where --export says.
  r = test::runJello("--time 0.1 --size 64x48 --export m2" + world, dir, "env -u DISPLAY");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(countFrames(dir + "/animation/rotate-001"), 4);
  EXPECT_EQ(countMeshes(dir + "/m2"), 4);
  test::removeTree(dir);
}

// --camera and --colouring change the frames; a camera or colouring the window cannot show is
// refused, naming the option, before anything is written.
TEST(CliFrames, CameraAndColouringChangeTheFramesAndBadOnesAreRefused) {
  const std::string dir = test::makeTempDir(), world = dataPath("jello.w");
  auto frame = [&](std::vector<std::string> args, const std::string& name) {
    args.insert(args.end(), {"--headless", "--steps", "0", "--size", "320x240", "--frames",
                             dir + "/" + name, world});
    const test::CommandResult r = test::runJelloArgs(args);
    EXPECT_EQ(r.status, 0) << r.err;
    return readJpeg(dir + "/" + name + "/0000.jpg");
  };
  const Image plain = frame({}, "plain");
  EXPECT_EQ(meanAbsoluteDifference(plain, frame({"--camera", "30,30,6"}, "same")), 0);
  EXPECT_GT(meanAbsoluteDifference(plain, frame({"--camera", "120,-10"}, "turned")), 2);
  EXPECT_GT(meanAbsoluteDifference(plain, frame({"--colouring", "Strain"}, "strain")), 0.5);
  for (const std::vector<std::string>& bad :
       std::vector<std::vector<std::string>>{{"--camera", "30"},
                                             {"--camera", "30,90"},
                                             {"--camera", "30,30,0.1"},
                                             {"--camera", "30,30,6,1"},
                                             {"--camera", "nan,30"},
                                             {"--colouring", "rainbow"}}) {
    std::vector<std::string> args = bad;
    args.insert(args.end(), {"--headless", "--frames", dir + "/never", world});
    const test::CommandResult r = test::runJelloArgs(args);
    EXPECT_EQ(r.status, 2) << bad[1];
    EXPECT_NE(r.err.find(bad[0] + ":"), std::string::npos) << r.err;
  }
  struct stat info;
  EXPECT_NE(::stat((dir + "/never").c_str(), &info), 0);
  test::removeTree(dir);
}

// --colouring stress and strain colour a headless frame of a jelly of elements.
TEST(CliFrames, StressAndStrainColourAJellyOfElements) {
  const std::string dir = test::makeTempDir(), scene = dir + "/elements.toml";
  test::writeText(scene, kElementScene);
  auto frame = [&](std::vector<std::string> args, const std::string& name) {
    args.insert(args.end(), {"--headless", "--steps", "0", "--size", "320x240", "--frames",
                             dir + "/" + name, scene});
    const test::CommandResult r = test::runJelloArgs(args);
    EXPECT_EQ(r.status, 0) << r.err;
    return readJpeg(dir + "/" + name + "/0000.jpg");
  };
  const Image plain = frame({}, "plain");
  EXPECT_GT(meanAbsoluteDifference(plain, frame({"--colouring", "STRESS"}, "stress")), 0.5);
  EXPECT_GT(meanAbsoluteDifference(plain, frame({"--colouring", "strain"}, "strain")), 0.5);
  test::removeTree(dir);
}

TEST(CliFrames, BadSizeIsRefused) {
  for (const char* size : {"640", "0x480", "640x480x3", "axb", "20000x20"}) {
    test::CommandResult r = test::runJello(std::string("--headless --size ") + size +
                                           " --frames /tmp/never '" + dataPath("rotate.w") + "'");
    EXPECT_EQ(r.status, 2) << size;
    EXPECT_NE(r.err.find("--size"), std::string::npos) << r.err;
  }
  struct stat info;
  EXPECT_NE(::stat("/tmp/never", &info), 0);
}

}  // namespace
}  // namespace jello
