// app/graphicsloader.cpp: jello's side of the pictures: load libjello_graphics.so when a run needs
// it, so that the GL libraries it links are loaded then and only then.

#include <dlfcn.h>
#include <unistd.h>

#include <climits>
#include <string>

#include "app/graphicsapi.h"

namespace jello {

namespace {

#ifdef JELLO_GRAPHICS_DIR
// The folder of the running executable, with a trailing slash; "" if unknown.
std::string executableFolder() {
  char path[PATH_MAX];
  ssize_t length = ::readlink("/proc/self/exe", path, sizeof path - 1);
  if (length <= 0) return {};
  std::string exe(path, static_cast<std::size_t>(length));
  return exe.substr(0, exe.find_last_of('/') + 1);
}
#endif

const GraphicsApi* load(std::string* why) {
#ifndef JELLO_GRAPHICS_DIR
  *why = "this build of jello has no GL";
  return nullptr;
#else
  // Beside the executable first (build/jello), then the build folder (the copy make puts in
  // the project's top folder).
  std::string error;
  for (const std::string& folder : {executableFolder(), std::string(JELLO_GRAPHICS_DIR) + "/"}) {
    if (folder.empty()) continue;
    const std::string path = folder + kGraphicsLibrary;
    if (::access(path.c_str(), F_OK) != 0) continue;
    void* library = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!library) {
      const char* message = ::dlerror();
      error = message ? message : path + ": cannot be loaded";
      continue;
    }
    auto entry = reinterpret_cast<const GraphicsApi* (*)()>(::dlsym(library, kGraphicsEntry));
    if (entry) return entry();
    error = path + ": no " + kGraphicsEntry;
  }
  *why = error.empty() ? std::string("cannot find ") + kGraphicsLibrary : error;
  return nullptr;
#endif
}

}  // namespace

const GraphicsApi* loadGraphics(std::string* why) {
  static std::string failure;
  static const GraphicsApi* api = load(&failure);
  if (!api) *why = failure;
  return api;
}

}  // namespace jello
