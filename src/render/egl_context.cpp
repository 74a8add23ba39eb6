// The EGL context: a display from the device or the surfaceless platform, a configless core context made
// current without a surface (EGL_KHR_no_config_context, EGL_KHR_surfaceless_context), and the GL entry
// points from eglGetProcAddress, which returns core functions too (EGL_KHR_get_all_proc_addresses).
#include "render/egl_context.hpp"

#include <cstdio>
#include <optional>
#include <stdexcept>
#include <vector>

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include "render/gl_loader.hpp"

namespace render {
namespace {

constexpr int kMaxDevices = 16;

std::string egl_error_text() {
  char code[16];
  std::snprintf(code, sizeof code, "0x%04x", static_cast<unsigned>(eglGetError()));
  return std::string("EGL error ") + code;
}

bool has_extension(const char* extensions, const std::string& name) {
  if (extensions == nullptr) return false;
  const std::string list = std::string(" ") + extensions + " ";
  return list.find(" " + name + " ") != std::string::npos;
}

template <typename Function>
Function egl_function(const char* name) {
  return reinterpret_cast<Function>(eglGetProcAddress(name));
}

struct OpenedDisplay {
  EGLDisplay display = EGL_NO_DISPLAY;
  EGLContext context = EGL_NO_CONTEXT;
};

// A configless context when the display allows one, else the first config that renders OpenGL.
EGLContext create_core_context(EGLDisplay display) {
  EGLConfig config = EGL_NO_CONFIG_KHR;
  if (!has_extension(eglQueryString(display, EGL_EXTENSIONS), "EGL_KHR_no_config_context")) {
    const EGLint wanted[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
    EGLint count = 0;
    if (!eglChooseConfig(display, wanted, &config, 1, &count) || count == 0) return EGL_NO_CONTEXT;
  }
  const EGLint attributes[] = {
      EGL_CONTEXT_MAJOR_VERSION,           4,       EGL_CONTEXT_MINOR_VERSION, 5, EGL_CONTEXT_OPENGL_PROFILE_MASK,
      EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
  return eglCreateContext(display, config, EGL_NO_CONTEXT, attributes);
}

// Initialises the display of `platform`/`native` and makes a core 4.5 context current on it; on failure
// appends "label: why" to `failures` and leaves nothing open.
std::optional<OpenedDisplay> open_display(EGLenum platform, void* native, const std::string& label,
                                          std::string& failures) {
  const auto fail = [&](const std::string& why) {
    failures += (failures.empty() ? "" : "; ") + label + ": " + why;
    return std::nullopt;
  };
  const auto get_display = egl_function<PFNEGLGETPLATFORMDISPLAYEXTPROC>("eglGetPlatformDisplayEXT");
  if (get_display == nullptr) return fail("no eglGetPlatformDisplayEXT");
  const EGLDisplay display = get_display(platform, native, nullptr);
  if (display == EGL_NO_DISPLAY) return fail("no display (" + egl_error_text() + ")");
  EGLint major = 0;
  EGLint minor = 0;
  if (!eglInitialize(display, &major, &minor)) return fail("eglInitialize failed (" + egl_error_text() + ")");
  const auto give_up = [&](const std::string& why) {
    eglTerminate(display);
    return fail(why);
  };
  if (!has_extension(eglQueryString(display, EGL_EXTENSIONS), "EGL_KHR_surfaceless_context")) {
    return give_up("no EGL_KHR_surfaceless_context");
  }
  if (!eglBindAPI(EGL_OPENGL_API)) return give_up("no desktop OpenGL (eglBindAPI failed)");
  const EGLContext context = create_core_context(display);
  if (context == EGL_NO_CONTEXT) return give_up("no OpenGL 4.5 core context (" + egl_error_text() + ")");
  if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) {
    eglDestroyContext(display, context);
    return give_up("eglMakeCurrent failed (" + egl_error_text() + ")");
  }
  return OpenedDisplay{display, context};
}

// The device platform's devices, split by Mesa's software flag (EGL_MESA_device_software).
struct Devices {
  std::vector<std::pair<EGLDeviceEXT, std::string>> hardware;
  std::vector<std::pair<EGLDeviceEXT, std::string>> software;
};

Devices query_devices() {
  Devices devices;
  if (!has_extension(eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS), "EGL_EXT_platform_device")) return devices;
  const auto query = egl_function<PFNEGLQUERYDEVICESEXTPROC>("eglQueryDevicesEXT");
  const auto query_string = egl_function<PFNEGLQUERYDEVICESTRINGEXTPROC>("eglQueryDeviceStringEXT");
  if (query == nullptr || query_string == nullptr) return devices;
  EGLDeviceEXT found[kMaxDevices];
  EGLint count = 0;
  if (!query(kMaxDevices, found, &count)) return devices;
  for (EGLint i = 0; i < count; ++i) {
    const std::string label = "device " + std::to_string(i);
    if (has_extension(query_string(found[i], EGL_EXTENSIONS), "EGL_MESA_device_software")) {
      devices.software.emplace_back(found[i], label + " (software)");
    } else {
      devices.hardware.emplace_back(found[i], label);
    }
  }
  return devices;
}

}  // namespace

EglContext::EglContext() {
  std::string failures;
  const Devices devices = query_devices();
  std::vector<std::pair<EGLenum, std::pair<void*, std::string>>> candidates;
  for (const auto& [device, label] : devices.hardware) candidates.push_back({EGL_PLATFORM_DEVICE_EXT, {device, label}});
  if (has_extension(eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS), "EGL_MESA_platform_surfaceless")) {
    candidates.push_back({EGL_PLATFORM_SURFACELESS_MESA, {EGL_DEFAULT_DISPLAY, "surfaceless"}});
  }
  for (const auto& [device, label] : devices.software) candidates.push_back({EGL_PLATFORM_DEVICE_EXT, {device, label}});
  for (const auto& [platform, native] : candidates) {
    if (const std::optional<OpenedDisplay> opened = open_display(platform, native.first, native.second, failures)) {
      display_ = opened->display;
      context_ = opened->context;
      platform_ = native.second;
      load_gl_functions([](const char* name) -> GlProc { return eglGetProcAddress(name); }, "EGL");
      return;
    }
  }
  throw std::runtime_error("EGL could not create an OpenGL 4.5 core-profile context without a window (" +
                           (failures.empty() ? std::string("no device or surfaceless platform") : failures) +
                           "; needs libegl1 with a vendor library: Debian's libegl-mesa0 for llvmpipe, or a GPU "
                           "driver's)");
}

EglContext::~EglContext() {
  eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  eglDestroyContext(display_, context_);
  eglTerminate(display_);
}

void EglContext::make_current() {
  if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_)) {
    throw std::runtime_error("EGL could not make its context current (" + egl_error_text() + ")");
  }
}

std::string EglContext::description() const {
  return "OpenGL " + gl_version_and_renderer() + " (EGL, " + platform_ + ")";
}

}  // namespace render
