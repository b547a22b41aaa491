// Presentation on an adopted window context: a linear blit into the default framebuffer.
#include "device.hpp"
#include "hal/layer.hpp"

namespace hal::gl {

void GlDevice::present(ImageHandle handle, std::uint32_t width, std::uint32_t height) {
  if (!context_.adopted())
    throw Error(ErrorKind::InvalidUsage, adapter_.name,
                "present needs a device on a window's context (DeviceOptions::make_current); this one is headless");
  make_current();
  const ImageObject& image = images_.get(handle.id, "image");
  if (!has(image.desc.usage, ImageUsage::CopySrc))
    throw Error(ErrorKind::InvalidUsage, image.desc.name, "presented images need CopySrc usage");
  glBindFramebuffer(GL_READ_FRAMEBUFFER, read_framebuffer_);
  glFramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, image.texture, 0);
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
  // GL's window origin is the bottom-left corner: flip so that the image's first row is on top.
  glBlitFramebuffer(0, 0, static_cast<GLint>(image.desc.width), static_cast<GLint>(image.desc.height), 0,
                    static_cast<GLint>(height), static_cast<GLint>(width), 0, GL_COLOR_BUFFER_BIT, GL_LINEAR);
  glFramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, 0, 0);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  check_gl(image.desc.name, "present (glBlitFramebuffer)");
}

void present(hal::Device& device, hal::ImageHandle image, std::uint32_t width, std::uint32_t height) {
  auto* gl = dynamic_cast<GlDevice*>(&hal::backend_of(device));
  if (!gl) throw Error(ErrorKind::InvalidUsage, device.adapter().name, "hal::gl::present needs an OpenGL device");
  gl->present(image, width, height);
}

}  // namespace hal::gl
