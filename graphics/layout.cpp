// layout.cpp: the window's layout as arithmetic; showCube.cpp and viewer.cpp draw what it places.

#include "graphics/layout.h"

#include <algorithm>

#include "graphics/showCube.h"

namespace jello {

namespace {

constexpr int kSmallWindowWidth = 560, kSmallWindowHeight = 400;  // below either: 1 pixel a dot
constexpr int kMarginDots = 4;
// The legends, in font dots.
constexpr int kSwatchDots = 8, kLegendGapDots = 3, kBarDots = 7, kBarMostDots = 80;
constexpr int kLegendLabelChars = 7;  // "-0.0005", "FORCE N": the longest a bar's end says
constexpr const char* kLongestColourTitle = "STRESS PA";  // over the bar and its labels
constexpr const char* kLongestSpringLabel = "STRUCTURAL";
constexpr const char* kHelpCut = "(MORE KEYS IN A LARGER WINDOW)";

std::string trimRight(std::string text) {
  while (!text.empty() && text.back() == ' ') text.pop_back();
  return text;
}

void append(std::vector<std::string>* lines, const std::vector<std::string>& more) {
  lines->insert(lines->end(), more.begin(), more.end());
}

// Status items two spaces apart, a new line where the next would not fit.
std::vector<std::string> flowItems(const std::vector<std::string>& items, int maxWidth, int scale) {
  std::vector<std::string> lines;
  std::string line;
  for (const std::string& item : items) {
    if (item.empty()) continue;
    if (!line.empty() && textWidth(line + "  " + item, scale) <= maxWidth) {
      line += "  " + item;
      continue;
    }
    if (!line.empty()) append(&lines, wrapText(line, maxWidth, scale));
    line = item;
  }
  if (!line.empty()) append(&lines, wrapText(line, maxWidth, scale));
  return lines;
}

// Lines one under the other from (x, y) at `scale`, returning the y below the last.
int place(const std::vector<std::string>& lines, int x, int y, int scale, TextRole role,
          std::vector<PlacedLine>* out) {
  for (const std::string& line : lines) {
    out->push_back({line, x, y, role, scale});
    y += kLineAdvance * scale;
  }
  return y;
}

// The key help in lines of at most `maxWidth` pixels: the keys in a column as wide as the
// longest, what they do wrapped beside them.
std::vector<std::string> helpLines(const std::vector<KeyLine>& help, int maxWidth, int scale) {
  std::size_t keys = 0;
  for (const KeyLine& line : help) keys = std::max(keys, line.keys.size() + 1);
  std::vector<std::string> lines;
  for (const KeyLine& line : help) {
    const std::string indent(keys, ' ');
    std::vector<std::string> does = wrapText(line.does, maxWidth - textWidth(indent, scale), scale);
    if (does.empty()) does.push_back("");
    for (std::size_t i = 0; i < does.size(); ++i) {
      std::string head = i == 0 ? line.keys : "";
      head.resize(keys, ' ');
      lines.push_back(head + does[i]);
    }
  }
  return lines;
}

// The help panel between `top` and `bottom`, at the overlay's scale or, where it does not fit,
// at 1 pixel a dot; its rectangle (empty when nothing fits).
PixelRect placeHelp(const std::vector<KeyLine>& help, const PixelRect& column, int top, int bottom,
                    int scale, std::vector<PlacedLine>* out) {
  std::vector<std::string> lines;
  std::size_t fits = 0;
  int pad = 0;
  for (int s = scale; s >= 1; --s) {
    scale = s;
    pad = 2 * s;
    lines = helpLines(help, column.width - 2 * pad, s);
    fits = static_cast<std::size_t>(std::max(0, (bottom - top - 2 * pad) / (kLineAdvance * s)));
    if (lines.size() <= fits) break;
  }
  if (lines.size() > fits) {
    lines.resize(fits);
    if (!lines.empty()) lines.back() = wrapText(kHelpCut, column.width - 2 * pad, scale).front();
  }
  if (lines.empty()) return {};
  place(lines, column.x + pad, top + pad, scale, TextRole::Help, out);
  return {column.x, top, column.width,
          static_cast<int>(lines.size()) * kLineAdvance * scale + 2 * pad};
}

}  // namespace

int textWidth(const std::string& text, int scale) {
  return static_cast<int>(text.size()) * kGlyphAdvance * scale;
}

bool overlap(const PixelRect& a, const PixelRect& b) {
  if (a.empty() || b.empty()) return false;
  return a.x < b.right() && b.x < a.right() && a.y < b.bottom() && b.y < a.bottom();
}

bool contains(const PixelRect& outer, const PixelRect& inner) {
  return inner.x >= outer.x && inner.y >= outer.y && inner.right() <= outer.right() &&
         inner.bottom() <= outer.bottom();
}

std::vector<std::string> wrapText(const std::string& text, int maxWidth, int scale) {
  const std::size_t most =
      std::max<std::size_t>(1, static_cast<std::size_t>(maxWidth / (kGlyphAdvance * scale)));
  std::vector<std::string> lines;
  std::string line;
  std::size_t start = 0;
  while (start <= text.size()) {
    std::size_t end = std::min(text.find(' ', start), text.size());
    std::string word = text.substr(start, end - start);
    start = end + 1;
    // Runs of spaces inside a line are kept (aligned help), at a break they go.
    if (line.empty() && word.empty()) continue;
    if (line.size() + 1 + word.size() <= most && !(line.empty() && word.size() > most)) {
      line += (line.empty() ? "" : " ") + word;
      continue;
    }
    if (!trimRight(line).empty()) lines.push_back(trimRight(line));
    line.clear();
    for (; word.size() > most; word.erase(0, most)) lines.push_back(word.substr(0, most));
    line = word;
  }
  if (!trimRight(line).empty()) lines.push_back(trimRight(line));
  return lines;
}

int textScale(int width, int height) {
  return width >= kSmallWindowWidth && height >= kSmallWindowHeight ? 2 : 1;
}

int edgeMargin(int scale) { return kMarginDots * scale; }

LegendLayout layoutLegends(int width, int height, int springKinds, bool colourLegend) {
  LegendLayout out;
  const int s = out.scale = textScale(width, height);
  const int margin = edgeMargin(s), line = kLineAdvance * s;
  if (springKinds > 0) {
    const int w = (kSwatchDots + kLegendGapDots) * s + textWidth(kLongestSpringLabel, s);
    out.springs = {width - margin - w, margin, w, springKinds * line};
    out.springLabelX = out.springs.x + (kSwatchDots + kLegendGapDots) * s;
  }
  if (colourLegend) {
    const int w = std::max((kBarDots + kLegendGapDots + kLegendLabelChars * kGlyphAdvance) * s,
                           textWidth(kLongestColourTitle, s));
    // The bar takes a third of the height, less where the springs' legend leaves less.
    const int above = out.springs.empty() ? margin : out.springs.bottom() + line;
    const int room = height - margin - above - line;
    const int barHeight = std::max(0, std::min({kBarMostDots * s, height / 3, room}));
    out.colours = {width - margin - w, height - margin - line - barHeight, w, line + barHeight};
    out.bar = {out.colours.x, out.colours.y + line, kBarDots * s, barHeight};
    out.barLabelX = out.bar.right() + kLegendGapDots * s;
  }
  return out;
}

OverlayLayout layoutOverlay(const OverlayText& text, int width, int height, int springKinds,
                            bool colourLegend) {
  OverlayLayout out;
  out.legends = layoutLegends(width, height, springKinds, colourLegend);
  const int s = out.scale = out.legends.scale;
  const int margin = edgeMargin(s), line = kLineAdvance * s, gap = line / 2;
  int right = width - margin;
  for (const PixelRect& legend : {out.legends.springs, out.legends.colours})
    if (!legend.empty()) right = std::min(right, legend.x - margin);
  out.column = {margin, margin, std::max(0, right - margin), std::max(0, height - 2 * margin)};
  const int x = out.column.x, w = out.column.width;

  int y = out.column.y;
  y = place(flowItems(text.status, w, s), x, y, s, TextRole::Status, &out.lines);
  y = place(wrapText(text.recording, w, s), x, y, s, TextRole::Recording, &out.lines);
  y = place(wrapText(text.colouring, w, s), x, y, s, TextRole::Status, &out.lines);
  if (y > out.column.y) out.top = {x, out.column.y, w, y - out.column.y};
  const int below = out.top.empty() ? out.column.y : out.top.bottom() + gap;

  // The help, asked for by a key, first; the messages from the bottom up in the space left, the
  // standing one first, the passing one under it.
  if (!text.help.empty())
    out.help = placeHelp(text.help, out.column, below, out.column.bottom(), s, &out.lines);
  const int above = out.help.empty() ? below : out.help.bottom() + gap;
  std::vector<std::string> standing = wrapText(text.standing, w, s);
  std::vector<std::string> messages = standing;
  append(&messages, wrapText(text.message, w, s));
  const int room = std::max(0, (out.column.bottom() - above) / line);
  messages.resize(std::min(messages.size(), static_cast<std::size_t>(room)));
  const int messagesTop = out.column.bottom() - static_cast<int>(messages.size()) * line;
  for (std::size_t i = 0; i < messages.size(); ++i)
    out.lines.push_back({messages[i], x, messagesTop + static_cast<int>(i) * line,
                         i < standing.size() ? TextRole::Standing : TextRole::Message, s});
  if (!messages.empty()) out.messages = {x, messagesTop, w, out.column.bottom() - messagesTop};
  return out;
}

double radiansPerPixel(int width, int height) {
  return kDragTurnDegrees * kPi / 180 / std::max(1, std::min(width, height));
}

// The keys, as the window's help lists them (the README's table says the same at more length).
const std::vector<KeyLine>& windowKeys() {
  static const std::vector<KeyLine> keys = {
      {"RIGHT-DRAG", "turn the camera"},
      {"LEFT-DRAG", "pull the cube (start on it)"},
      {"Z X E", "zoom in, out; camera reset"},
      {"V", "wireframe"},
      {"S H B", "springs by kind, as lines"},
      {"C", "colour: strain, force, stress, friction"},
      {"F", "hold or free colour scale"},
      {"ARROWS", "push the jelly as seen"},
      {"J", "make it jump"},
      {"P", "pause, run on"},
      {"R", "real-time pacing"},
      {"SPACE", "record frames, stop"},
      {"W", "save the window as a JPEG"},
      {"G", "the panel"},
      {"? K", "this help"},
      {"ESC", "quit"},
  };
  return keys;
}

}  // namespace jello
