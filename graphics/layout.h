// layout.h: where the window puts its text and legends, and how far a drag turns the camera, as
// plain arithmetic on pixels (no GL), so that it can be tested without a display.
//
// Pixels count from the window's top-left corner, x to the right, y down. The layout (README: The
// viewer) is, by construction, one where nothing overlaps:
//   - a legend column at the right edge, only while a legend is shown: the springs' legend at its
//     top, the colour legend at its bottom (both drawn by drawPicture, so saved frames have them);
//   - the text column, the rest of the width: the status lines at its top (the status, the
//     recording, the colouring, one under the other), the messages wrapped at its bottom, and the
//     key help, when shown, in the space between them.
// Text is drawn 2 pixels a font dot, or 1 in small windows, so that it fits at 320x240.
#pragma once

#include <string>
#include <vector>

namespace jello {

// The built-in bitmap font (drawText in showCube.cpp): 5x7 dots a glyph, 6 dots from one glyph to
// the next, 9 dots from one line to the next (the glyph, its shadow and a gap).
constexpr int kGlyphWidth = 5, kGlyphHeight = 7, kGlyphAdvance = 6, kLineAdvance = 9;

// Width in pixels of `text` drawn at `scale` pixels a font dot.
int textWidth(const std::string& text, int scale);

struct PixelRect {
  int x = 0, y = 0, width = 0, height = 0;
  bool empty() const { return width <= 0 || height <= 0; }
  int right() const { return x + width; }    // one past the last column
  int bottom() const { return y + height; }  // one past the last row
};
// True when the two share a pixel (an empty rectangle shares none).
bool overlap(const PixelRect& a, const PixelRect& b);
bool contains(const PixelRect& outer, const PixelRect& inner);

// `text` in lines of at most `maxWidth` pixels at `scale`: broken at spaces, and inside a word only
// where the word alone is wider; every line holds at least one character.
std::vector<std::string> wrapText(const std::string& text, int maxWidth, int scale);

// Pixels a font dot for a window's text: 2, or 1 in a window smaller than 560x400.
int textScale(int width, int height);
// The gap between the window's edge and anything drawn, pixels.
int edgeMargin(int scale);

// The legends in the right-hand column.
struct LegendLayout {
  int scale = 2;
  PixelRect springs;     // a line per spring kind shown: a swatch of its colour, then its name
  int springLabelX = 0;  // where the names start
  PixelRect colours;     // the title line, then the colour bar with its end values at its right
  PixelRect bar;         // the colour bar, inside `colours`
  int barLabelX = 0;     // where the end values start
};
// `springKinds`: how many spring kinds are drawn (0 to 3); `colourLegend`: a coloured surface.
LegendLayout layoutLegends(int width, int height, int springKinds, bool colourLegend);

// A line of the key help: the keys in a column of their own, what they do beside them.
struct KeyLine {
  std::string keys, does;
};

// What the overlay says; the layout places it.
struct OverlayText {
  std::vector<std::string> status;  // short items, flowed into lines two spaces apart
  std::string recording;            // "SAVING 12/300 INTO ANIMATION/", or ""
  std::string colouring;            // the surface colouring and its scale, or ""
  std::vector<KeyLine> help;        // the key help; empty when hidden
  std::string standing;  // the run's state while it lasts (diverged, reached --time), or ""
  std::string message;   // the latest passing message, or ""
};

enum class TextRole { Status, Recording, Help, Standing, Message };

struct PlacedLine {
  std::string text;
  int x = 0, y = 0;  // top-left of the first glyph
  TextRole role = TextRole::Status;
  int scale = 2;  // pixels a font dot
};

struct OverlayLayout {
  int scale = 2;
  std::vector<PlacedLine> lines;
  PixelRect top;       // status, recording and colouring lines
  PixelRect help;      // the key help's panel; empty when hidden
  PixelRect messages;  // the standing and passing messages
  PixelRect column;    // the text column, which holds all three
  LegendLayout legends;
};
// The help, when shown, comes first (a key asked for it, and takes it away): it is drawn at 1 pixel
// a dot when it does not fit at the overlay's scale, and lines that still do not fit are dropped,
// the last kept one saying so. Messages keep their first lines that fit in the rest (stderr has
// them whole).
OverlayLayout layoutOverlay(const OverlayText& text, int width, int height, int springKinds,
                            bool colourLegend);

// The camera's turn per pixel of a right-drag: a drag across the window's shorter side turns it by
// kDragTurnDegrees, so that the same share of the window turns the view as much at any size
// (160 px of a 640x480 window: 45 degrees).
constexpr double kDragTurnDegrees = 135;
double radiansPerPixel(int width, int height);

// The window's keys as its help (? or k) lists them; the README's table says the same at more
// length.
const std::vector<KeyLine>& windowKeys();

}  // namespace jello
