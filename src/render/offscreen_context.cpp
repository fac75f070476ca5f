#include "render/offscreen_context.hpp"

#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <algorithm>
#include <cstdio>
#include <mutex>
#include <stdexcept>
#include <string>

namespace imasim::render {

struct OffscreenContext::Egl {
  EGLDisplay display = EGL_NO_DISPLAY;
  EGLContext context = EGL_NO_CONTEXT;
};

namespace {

[[noreturn]] void fail(const std::string& what) {
  throw std::runtime_error("offscreen rendering: " + what + " (EGL error 0x" + [] {
    char b[16];
    std::snprintf(b, sizeof b, "%x", unsigned(eglGetError()));
    return std::string(b);
  }() + "); Mesa's EGL (libegl-mesa0, libgl1-mesa-dri) is needed");
}

// Contexts alive in this process. EGL gives every caller the same surfaceless display, and
// eglTerminate ends every context on it: only the last context to go may terminate it.
std::mutex live_mutex;
int live_contexts = 0;

}  // namespace

OffscreenContext::OffscreenContext(int width, int height)
    : egl_(std::make_unique<Egl>()), width_(width), height_(height) {
  if (width < 1 || height < 1 || width > 8192 || height > 8192)
    throw std::invalid_argument("offscreen rendering: the image must be 1 to 8192 pixels a side");
  // Surfaceless: no window system at all, which is what a headless machine has.
  egl_->display =
      eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  if (egl_->display == EGL_NO_DISPLAY) fail("no surfaceless EGL display");
  EGLint major = 0, minor = 0;
  if (!eglInitialize(egl_->display, &major, &minor)) fail("eglInitialize failed");
  if (!eglBindAPI(EGL_OPENGL_API)) fail("no desktop OpenGL through EGL");
  const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                               3,
                               EGL_CONTEXT_MINOR_VERSION,
                               3,
                               EGL_CONTEXT_OPENGL_PROFILE_MASK,
                               EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                               EGL_NONE};
  egl_->context = eglCreateContext(egl_->display, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes);
  if (egl_->context == EGL_NO_CONTEXT) fail("no OpenGL 3.3 core context");
  if (!eglMakeCurrent(egl_->display, EGL_NO_SURFACE, EGL_NO_SURFACE, egl_->context))
    fail("cannot make the context current");

  glGenFramebuffers(1, &framebuffer_);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  glGenRenderbuffers(1, &colour_);
  glBindRenderbuffer(GL_RENDERBUFFER, colour_);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour_);
  glGenRenderbuffers(1, &depth_);
  glBindRenderbuffer(GL_RENDERBUFFER, depth_);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    throw std::runtime_error("offscreen rendering: the framebuffer is incomplete");
  const std::lock_guard<std::mutex> lock(live_mutex);
  ++live_contexts;
}

OffscreenContext::~OffscreenContext() {
  // Its own objects, with its own context current (another may have been made current since).
  make_current();
  glDeleteRenderbuffers(1, &depth_);
  glDeleteRenderbuffers(1, &colour_);
  glDeleteFramebuffers(1, &framebuffer_);
  eglMakeCurrent(egl_->display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  eglDestroyContext(egl_->display, egl_->context);
  const std::lock_guard<std::mutex> lock(live_mutex);
  if (--live_contexts == 0) eglTerminate(egl_->display);
}

void OffscreenContext::make_current() {
  if (eglGetCurrentContext() != egl_->context)
    eglMakeCurrent(egl_->display, EGL_NO_SURFACE, EGL_NO_SURFACE, egl_->context);
}

void OffscreenContext::bind() {
  make_current();
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  glViewport(0, 0, width_, height_);
}

std::vector<std::uint8_t> OffscreenContext::read_rgb() {
  const std::size_t w = std::size_t(width_), h = std::size_t(height_);
  std::vector<std::uint8_t> raw(w * h * 3), out(w * h * 3);
  make_current();
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width_, height_, GL_RGB, GL_UNSIGNED_BYTE, raw.data());
  // OpenGL's rows start at the bottom; images' at the top.
  for (std::size_t y = 0; y < h; ++y)
    std::copy_n(raw.data() + (h - 1 - y) * w * 3, w * 3, out.data() + y * w * 3);
  return out;
}

std::vector<float> OffscreenContext::read_depth() {
  const std::size_t w = std::size_t(width_), h = std::size_t(height_);
  std::vector<float> raw(w * h), out(w * h);
  make_current();
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width_, height_, GL_DEPTH_COMPONENT, GL_FLOAT, raw.data());
  for (std::size_t y = 0; y < h; ++y)
    std::copy_n(raw.data() + (h - 1 - y) * w, w, out.data() + y * w);
  return out;
}

const char* OffscreenContext::renderer_name() const {
  return reinterpret_cast<const char*>(glGetString(GL_RENDERER));
}

}  // namespace imasim::render
