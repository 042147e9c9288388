// The window's layout (graphics/layout.h): wrapped text, an overlay where nothing overlaps at
// the default and the smallest usual window sizes, and the camera's turn per pixel dragged.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "graphics/layout.h"

namespace jello {
namespace {

std::string joinWords(const std::vector<std::string>& lines) {
  std::string all;
  for (const std::string& line : lines) all += line + " ";
  std::istringstream words(all);
  std::string word, out;
  while (words >> word) out += word;
  return out;
}

TEST(Layout, WrappedTextBreaksAtSpacesKeepsEveryCharacterAndFitsTheWidth) {
  const std::string text =
      "diverged at step 2 (t=0.1 s): point p[0][0][0] is more than 100 m from the origin; dt=0.05 "
      "exceeds RK4's stable limit 0.00127 for this world; try --dt 0.001 or --integrator IMPLICIT";
  for (int scale : {1, 2})
    for (int width : {120, 237, 474, 2000}) {
      std::vector<std::string> lines = wrapText(text, width, scale);
      ASSERT_FALSE(lines.empty());
      for (const std::string& line : lines) {
        EXPECT_LE(textWidth(line, scale), width) << line;
        EXPECT_NE(line.front(), ' ');
        EXPECT_NE(line.back(), ' ');
      }
      EXPECT_EQ(joinWords(lines), joinWords({text}));
      if (textWidth(text, scale) <= width) {
        EXPECT_EQ(lines.size(), 1u);
      }
    }
  EXPECT_EQ(wrapText("one two three", textWidth("one two", 1), 1),
            (std::vector<std::string>{"one two", "three"}));
  // A word wider than the line is cut; no line is empty, however narrow.
  EXPECT_EQ(wrapText("abcdefgh", textWidth("abc", 1), 1),
            (std::vector<std::string>{"abc", "def", "gh"}));
  EXPECT_EQ(wrapText("ab", 1, 1), (std::vector<std::string>{"a", "b"}));
  EXPECT_TRUE(wrapText("", 100, 1).empty());
}

// Everything the overlay can show at once, at its longest.
OverlayText everything() {
  OverlayText text;
  text.status = {"T=1234.567 S", "IMPLICIT DT=0.000123", "123456 STEPS/S", "REAL TIME", "PAUSED",
                 "? KEYS"};
  text.recording = "SAVING 9999/10000 INTO ANIMATION/ROTATE-001/";
  text.colouring = "force SCALE FITS EACH FRAME (F HOLDS)";
  text.help = windowKeys();
  text.standing =
      "diverged at step 2 (t=0.1 s): point p[0][0][0] is more than 100 m from the origin; dt=0.05 "
      "exceeds RK4's stable limit 0.00127 for this world; try --dt 0.001 or --integrator IMPLICIT "
      "(paused on the last sane state; ESC quits)";
  text.message =
      "no point of the cube near the cursor: left-drag from the cube's surface to pull it";
  return text;
}

PixelRect lineRect(const PlacedLine& line) {
  return {line.x, line.y, textWidth(line.text, line.scale), (kGlyphHeight + 1) * line.scale};
}

TEST(Layout, NothingOverlapsAtTheDefaultAndTheSmallestUsualWindow) {
  for (auto [width, height] : {std::pair{640, 480}, std::pair{320, 240}, std::pair{800, 600}}) {
    SCOPED_TRACE(std::to_string(width) + "x" + std::to_string(height));
    const PixelRect window{0, 0, width, height};
    const OverlayLayout layout = layoutOverlay(everything(), width, height, 3, true);
    const std::vector<PixelRect> blocks = {layout.top, layout.help, layout.messages,
                                           layout.legends.springs, layout.legends.colours};
    for (std::size_t i = 0; i < blocks.size(); ++i) {
      EXPECT_FALSE(blocks[i].empty()) << "block " << i;
      EXPECT_TRUE(contains(window, blocks[i])) << "block " << i;
      for (std::size_t j = i + 1; j < blocks.size(); ++j)
        EXPECT_FALSE(overlap(blocks[i], blocks[j])) << "blocks " << i << " and " << j;
    }
    EXPECT_TRUE(contains(layout.legends.colours, layout.legends.bar));
    for (std::size_t i = 0; i < layout.lines.size(); ++i) {
      const PixelRect a = lineRect(layout.lines[i]);
      EXPECT_TRUE(contains(layout.column, a)) << layout.lines[i].text;
      for (std::size_t j = i + 1; j < layout.lines.size(); ++j)
        EXPECT_FALSE(overlap(a, lineRect(layout.lines[j])))
            << layout.lines[i].text << " | " << layout.lines[j].text;
    }
    // The whole help fits (ESC is its last line); without it, the messages are shown whole.
    std::string all;
    for (const PlacedLine& line : layout.lines) all += line.text + "\n";
    EXPECT_NE(all.find("ESC"), std::string::npos) << all;
    EXPECT_EQ(all.find("LARGER WINDOW"), std::string::npos) << all;
    OverlayText noHelp = everything();
    noHelp.help.clear();
    all.clear();
    for (const PlacedLine& line : layoutOverlay(noHelp, width, height, 3, true).lines)
      all += line.text + " ";
    EXPECT_NE(all.find("IMPLICIT (paused"), std::string::npos) << all;
    EXPECT_NE(all.find("to pull it"), std::string::npos) << all;
  }
}

TEST(Layout, StatusItemsShareALineOnlyWhereTheyFitAndTheRecordingHasALineOfItsOwn) {
  OverlayText text;
  text.status = {"T=0.500 S", "RK4 DT=0.001", "REAL TIME", "PAUSED"};
  text.recording = "SAVING 3/300 INTO ANIMATION/";
  OverlayLayout wide = layoutOverlay(text, 640, 480, 0, false);
  ASSERT_EQ(wide.lines.size(), 2u);
  EXPECT_EQ(wide.lines[0].text, "T=0.500 S  RK4 DT=0.001  REAL TIME  PAUSED");
  EXPECT_EQ(wide.lines[1].role, TextRole::Recording);
  EXPECT_GT(wide.lines[1].y, wide.lines[0].y);
  OverlayLayout narrow = layoutOverlay(text, 100, 240, 0, false);
  for (const PlacedLine& line : narrow.lines) EXPECT_LE(textWidth(line.text, line.scale), 92);
}

TEST(Layout, AHelpTooLongForTheWindowSaysSoInItsLastLine) {
  OverlayText text = everything();
  for (int i = 0; i < 40; ++i) text.help.push_back({"X", "more"});
  const OverlayLayout layout = layoutOverlay(text, 320, 240, 0, false);
  std::string last;
  for (const PlacedLine& line : layout.lines)
    if (line.role == TextRole::Help) last = line.text;
  EXPECT_NE(last.find("LARGER WINDOW"), std::string::npos) << last;
  EXPECT_FALSE(overlap(layout.help, layout.messages));
}

TEST(Layout, ARightDragOfAQuarterOfTheWindowTurnsTheCameraBy45Degrees) {
  const double degreesPerRadian = 180 / std::acos(-1.0);
  EXPECT_NEAR(160 * radiansPerPixel(640, 480) * degreesPerRadian, 45, 0.5);
  EXPECT_NEAR(80 * radiansPerPixel(320, 240) * degreesPerRadian, 45, 0.5);
  EXPECT_NEAR(480 * radiansPerPixel(640, 480) * degreesPerRadian, kDragTurnDegrees, 1e-9);
  EXPECT_GT(radiansPerPixel(1, 1), 0);
}

}  // namespace
}  // namespace jello
