// io/scenetable.h: the scene reader's view of a TOML table (scenereader.cpp): every key known,
// every value checked, and every refusal one line "FILE:LINE: what (key)", never toml++'s words.
#pragma once

#include <toml++/toml.h>

#include <cmath>
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

#include "core/nearest.h"
#include "io/inputerror.h"
#include "model/vec3.h"

namespace jello {

// `text` in one line: a control character (a quoted TOML key may hold one, and toml++ quotes
// the character it stopped at) is named instead, as <newline>, <tab> or <U+00NN>. Not through
// printable(): printError escapes the whole message again, which would double its backslashes.
inline std::string oneLine(std::string_view text) {
  std::string out;
  for (char c : text) {
    const auto u = static_cast<unsigned char>(c);
    if (u >= 0x20 && u != 0x7f)
      out += c;
    else if (c == '\n')
      out += "<newline>";
    else if (c == '\t')
      out += "<tab>";
    else {
      static const char kHex[] = "0123456789ABCDEF";
      out += "<U+00";
      out += kHex[u >> 4];
      out += kHex[u & 15];
      out += '>';
    }
  }
  return out;
}

// Reads the scene's keys, refusing any it does not know and any value it cannot use.
class Reader {
 public:
  Reader(std::string name, std::string folder)
      : name_(std::move(name)), folder_(std::move(folder)) {}

  [[noreturn]] void fail(const toml::node& at, const std::string& key,
                         const std::string& what) const {
    throw InputError(name_ + ":" + std::to_string(at.source().begin.line) + ": " + oneLine(what) +
                     " (" + oneLine(key) + ")");
  }

  // Every key of `table` is one of `known`; an unknown one is named with the key it most likely
  // meant (core/nearest.h), as the command line names an option.
  void onlyKeys(const toml::table& table, const std::string& path,
                const std::vector<std::string>& known) const {
    for (auto&& [key, node] : table) {
      bool ok = false;
      for (const std::string& k : known) ok = ok || key.str() == k;
      if (ok) continue;
      const std::string meant = nearestName(std::string(key.str()), known);
      throw InputError(name_ + ":" + std::to_string(node.source().begin.line) + ": unknown key (" +
                       oneLine(path + std::string(key.str())) + ")" +
                       (meant.empty() ? "" : "; did you mean " + oneLine(path + meant) + "?"));
    }
  }

  // A finite number, at least `lowest` (or above it when `strictly`).
  std::optional<double> number(const toml::table& table, const std::string& path, const char* key,
                               double lowest = -INFINITY, bool strictly = false) const {
    const toml::node* node = table.get(key);
    if (!node) return std::nullopt;
    const std::string full = path + key;
    std::optional<double> value = node->is_number() ? node->value<double>() : std::nullopt;
    if (!value) fail(*node, full, "expected a number");
    if (!std::isfinite(*value)) fail(*node, full, "is not finite");
    checkMagnitude(*node, full, *value);
    if (strictly ? !(*value > lowest) : !(*value >= lowest))
      fail(*node, full,
           std::string("must be ") + (strictly ? "above " : "at least ") + textOf(lowest));
    return value;
  }

  void checkMagnitude(const toml::node& at, const std::string& key, double value) const {
    if (std::fabs(value) > kLargestSceneNumber)
      fail(at, key, "is beyond " + textOf(kLargestSceneNumber) + " in magnitude");
  }

  std::optional<Vec3> vector(const toml::table& table, const std::string& path,
                             const char* key) const {
    const toml::node* node = table.get(key);
    if (!node) return std::nullopt;
    const toml::array* array = node->as_array();
    if (!array || array->size() != 3) fail(*node, path + key, "expected 3 numbers [x, y, z]");
    double xyz[3];
    for (int i = 0; i < 3; ++i) {
      const toml::node& item = *array->get(i);
      std::optional<double> value = item.is_number() ? item.value<double>() : std::nullopt;
      if (!value) fail(item, path + key, "expected 3 numbers [x, y, z]");
      if (!std::isfinite(*value)) fail(item, path + key, "is not finite");
      checkMagnitude(item, path + key, *value);
      xyz[i] = *value;
    }
    return Vec3{xyz[0], xyz[1], xyz[2]};
  }

  const toml::table* table(const toml::table& parent, const std::string& path,
                           const char* key) const {
    const toml::node* node = parent.get(key);
    if (!node) return nullptr;
    if (!node->is_table()) fail(*node, path + key, "expected a table");
    return node->as_table();
  }

  // An array of tables ([[sphere]]), each handed to `each` with its path ("sphere[2].").
  template <class Each>
  void tables(const toml::table& parent, const char* key, Each each) const {
    const toml::node* node = parent.get(key);
    if (!node) return;
    const toml::array* array = node->as_array();
    if (!array || !array->is_array_of_tables())
      fail(*node, key, "expected [[" + std::string(key) + "]] tables");
    for (std::size_t i = 0; i < array->size(); ++i)
      each(*array->get(i)->as_table(), std::string(key) + "[" + std::to_string(i + 1) + "].");
  }

  const std::string& name() const { return name_; }
  // A path the scene file names (a world, a model): absolute as it is, else relative to the
  // scene file's folder (docs/scenes.md).
  // Each is kept as one of the files the scene reads (inputs()).
  std::string pathFromScene(const std::string& path) const {
    std::string full =
        path.empty() || path[0] == '/' || folder_.empty() ? path : folder_ + "/" + path;
    inputs_.push_back(full);
    return full;
  }
  // Every file the scene reads besides itself, as named (a world, a state, a mesh, a TetGen
  // mesh's two files): what --dump and --save-state never replace.
  void noteInput(const std::string& path) const { inputs_.push_back(path); }
  const std::vector<std::string>& inputs() const { return inputs_; }

 public:
  static std::string textOf(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", value);
    return text;
  }

 private:
  std::string name_, folder_;
  mutable std::vector<std::string> inputs_;
};

}  // namespace jello
