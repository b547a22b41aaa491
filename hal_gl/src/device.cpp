// The OpenGL device: creation and destruction of objects, submission, host transfers, timers,
// and the GL side of each command a list replays.
#include "device.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "program_dump.hpp"

namespace hal::gl {
namespace {

std::string gl_string(GLenum name) {
  const auto* s = reinterpret_cast<const char*>(glGetString(name));
  return s ? s : "";
}

GLint gl_int(GLenum name) {
  GLint v = 0;
  glGetIntegerv(name, &v);
  return v;
}

void GLAPIENTRY debug_message(GLenum, GLenum type, GLuint, GLenum severity, GLsizei, const GLchar* message,
                              const void* user) {
  if (type != GL_DEBUG_TYPE_ERROR && severity != GL_DEBUG_SEVERITY_HIGH) return;
  const auto& options = *static_cast<const DeviceOptions*>(user);
  if (options.on_message)
    options.on_message(message);
  else
    std::fprintf(stderr, "OpenGL: %s\n", message);
}

// glMemoryBarrier bits that make incoherent shader writes visible to the next use in `after`.
// A compute-written image later copied needs the image-access bit too (wgpu #8473).
GLbitfield barrier_bits(State after) {
  switch (after) {
    case State::ShaderRead:
      return GL_SHADER_STORAGE_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT |
             GL_UNIFORM_BARRIER_BIT;
    case State::ShaderWrite:
      return GL_SHADER_STORAGE_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT;
    case State::CopySrc:
    case State::CopyDst:
      return GL_BUFFER_UPDATE_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT | GL_PIXEL_BUFFER_BARRIER_BIT |
             GL_SHADER_IMAGE_ACCESS_BARRIER_BIT;
    case State::Present:
      return GL_FRAMEBUFFER_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT;
    default:
      return 0;
  }
}

GLenum image_access(Access access) {
  switch (access) {
    case Access::Read:
      return GL_READ_ONLY;
    case Access::Write:
      return GL_WRITE_ONLY;
    case Access::ReadWrite:
      return GL_READ_WRITE;
  }
  return GL_READ_WRITE;
}

// ASVGF_GL_SHADERS as set ("" when unset).
std::string shaders_variable() {
  const char* chosen = std::getenv("ASVGF_GL_SHADERS");
  return chosen ? chosen : "";
}

// Whether programs are loaded as SPIR-V (GL_ARB_gl_spirv) rather than compiled from GLSL, on
// OpenGL 4.5: ASVGF_GL_SHADERS=glsl or spirv chooses; unset, GLSL. No driver is measured faster
// from SPIR-V now (docs/performance.md): NVIDIA's was (path tracing 3.94 against 4.68 ms on the
// H100) until the GLSL translation stopped re-reading buffers at each use (3.32 against 3.20 ms
// since), and Mesa's llvmpipe runs the OpenGL suites slower from SPIR-V (78 s of CPU against 20).
// OpenGL ES has no SPIR-V path: it always compiles ESSL.
bool spirv_shaders(bool es, const std::string& adapter) {
  if (const std::string problem = environment_problem(); !problem.empty())
    throw Error(ErrorKind::InvalidUsage, "", problem);
  const std::string choice = shaders_variable();
  if (es || choice != "spirv") return false;
  if (!epoxy_has_gl_extension("GL_ARB_gl_spirv"))
    throw Error(ErrorKind::Unsupported, adapter, "ASVGF_GL_SHADERS=spirv: the context lacks GL_ARB_gl_spirv");
  return true;
}

}  // namespace

GlDevice::GlDevice(const DeviceOptions& options)
    : options_(options),
      context_(options.make_current ? Context(options.flavour, options.make_current) : Context(options.flavour)) {
  const bool es = options.flavour == Flavour::Gles;
  adapter_.name = gl_string(GL_RENDERER);
  adapter_.driver = gl_string(GL_VENDOR) + " " + gl_string(GL_VERSION);
  adapter_.api_version = gl_string(GL_VERSION);
  adapter_.type = adapter_.name.find("llvmpipe") != std::string::npos ? DeviceType::Cpu : DeviceType::Other;
  const int version = epoxy_gl_version();
  if (es ? version < 31 : version < 45)
    throw Error(ErrorKind::Unsupported, adapter_.name,
                "the context is " + adapter_.api_version + "; compute needs " + (es ? "OpenGL ES 3.1" : "OpenGL 4.5"));
  spirv_shaders_ = spirv_shaders(es, adapter_.name);
  adapter_.api_version += spirv_shaders_ ? ", programs from SPIR-V (GL_ARB_gl_spirv)"
                          : es           ? ", programs from ESSL"
                                         : ", programs from GLSL";
  immutable_buffers_ = !es || epoxy_has_gl_extension("GL_EXT_buffer_storage");
  capabilities_.ray_query = false;
  capabilities_.acceleration_structures = false;
  capabilities_.fp16_storage = false;
  capabilities_.timestamps = !es || epoxy_has_gl_extension("GL_EXT_disjoint_timer_query");
  capabilities_.subgroup_size = 0;
  capabilities_.max_image_dimension = static_cast<std::uint32_t>(gl_int(GL_MAX_TEXTURE_SIZE));
  capabilities_.max_storage_buffer_range = static_cast<std::uint64_t>(gl_int(GL_MAX_SHADER_STORAGE_BLOCK_SIZE));
  capabilities_.max_buffer_size = std::uint64_t{1} << 31;  // GLsizeiptr offsets stay safe on every driver
  if ((!es && version >= 43) || (es && version >= 32) || epoxy_has_gl_extension("GL_KHR_debug")) {
    glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    glDebugMessageCallback(debug_message, &options_);
    debug_output_ = true;
  }
  glGenBuffers(1, &uniform_buffer_);
  glGenFramebuffers(1, &read_framebuffer_);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  check_gl(adapter_.name, "context setup");
}

GlDevice::~GlDevice() {
  try {
    make_current();
    glFinish();
    for (auto& [id, b] : buffers_.all()) glDeleteBuffers(1, &b.buffer);
    for (auto& [id, i] : images_.all()) glDeleteTextures(1, &i.texture);
    for (auto& [id, p] : pipelines_.all()) glDeleteProgram(p.program);
    for (auto& [id, t] : timers_.all()) glDeleteQueries(static_cast<GLsizei>(t.queries.size()), t.queries.data());
    glDeleteBuffers(1, &uniform_buffer_);
    if (readback_buffer_) glDeleteBuffers(1, &readback_buffer_);
    glDeleteFramebuffers(1, &read_framebuffer_);
    gpu_clear_.reset();
    if (debug_output_) glDebugMessageCallback(nullptr, nullptr);
  } catch (...) {
    // A context that cannot be made current has nothing left to release.
  }
}

void GlDevice::check_gl(const std::string& object, const char* what) {
  const GLenum error = glGetError();
  if (error == GL_NO_ERROR) return;
  while (glGetError() != GL_NO_ERROR) {
  }
  char code[16];
  std::snprintf(code, sizeof code, "0x%04x", error);
  if (error == GL_OUT_OF_MEMORY) throw Error(ErrorKind::OutOfMemory, object, std::string(what) + ": GL_OUT_OF_MEMORY");
  throw Error(ErrorKind::Backend, object, std::string(what) + ": GL error " + code);
}

BufferHandle GlDevice::create_buffer(const BufferDesc& desc) {
  make_current();
  BufferObject object{desc, 0};
  glGenBuffers(1, &object.buffer);
  glBindBuffer(GL_COPY_WRITE_BUFFER, object.buffer);
  const auto size = static_cast<GLsizeiptr>(desc.size);
  // Dynamic storage: uploads write with glBufferSubData.
  if (immutable_buffers_)
    glBufferStorage(GL_COPY_WRITE_BUFFER, size, nullptr, GL_DYNAMIC_STORAGE_BIT);
  else
    glBufferData(GL_COPY_WRITE_BUFFER, size, nullptr, GL_DYNAMIC_COPY);
  glBindBuffer(GL_COPY_WRITE_BUFFER, 0);
  try {
    check_gl(desc.name, immutable_buffers_ ? "glBufferStorage" : "glBufferData");
  } catch (...) {
    glDeleteBuffers(1, &object.buffer);
    throw;
  }
  return BufferHandle{buffers_.add(std::move(object))};
}

ImageHandle GlDevice::create_image(const ImageDesc& desc) {
  make_current();
  ImageObject object{desc, 0, gl_format(desc.format)};
  glGenTextures(1, &object.texture);
  glBindTexture(GL_TEXTURE_2D, object.texture);
  glTexStorage2D(GL_TEXTURE_2D, 1, object.format.internal, static_cast<GLsizei>(desc.width),
                 static_cast<GLsizei>(desc.height));
  // texelFetch ignores filtering, but integer textures are incomplete with linear filters.
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glBindTexture(GL_TEXTURE_2D, 0);
  try {
    check_gl(desc.name, "glTexStorage2D");
  } catch (...) {
    glDeleteTextures(1, &object.texture);
    throw;
  }
  return ImageHandle{images_.add(std::move(object))};
}

PipelineHandle GlDevice::create_pipeline(const ComputePipelineDesc& desc) {
  make_current();
  const ShaderInfo& shader = *desc.shader;
  const bool es = context_.flavour() == Flavour::Gles;
  const std::string replacement = program_source_override(shader.name, es);
  const std::string_view source = !replacement.empty() ? std::string_view(replacement)
                                  : es                 ? shader.source("essl")
                                                       : shader.source("glsl");
  if (source.empty())
    throw Error(ErrorKind::Unsupported, desc.name,
                "shader '" + std::string(shader.name) + "' has no " +
                    (context_.flavour() == Flavour::Gles ? "ESSL" : "GLSL") + " source (ray-query variants have none)");
  // Over a limit, the driver's link error would not say which: name the kind and both counts.
  struct Limit {
    BindingKind kind;
    GLenum query;
    const char* what;
  };
  const Limit limits[] = {{BindingKind::StorageBuffer, GL_MAX_COMPUTE_SHADER_STORAGE_BLOCKS, "storage blocks"},
                          {BindingKind::StorageImage, GL_MAX_COMPUTE_IMAGE_UNIFORMS, "image uniforms"},
                          {BindingKind::SampledImage, GL_MAX_COMPUTE_TEXTURE_IMAGE_UNITS, "textures"},
                          {BindingKind::UniformBuffer, GL_MAX_COMPUTE_UNIFORM_BLOCKS, "uniform blocks"}};
  for (const Limit& l : limits) {
    const auto used = std::count_if(shader.bindings.begin(), shader.bindings.end(),
                                    [&](const ShaderBinding& b) { return b.kind == l.kind; });
    if (used > gl_int(l.query))
      throw Error(ErrorKind::Unsupported, desc.name,
                  "shader '" + std::string(shader.name) + "' uses " + std::to_string(used) + " " + l.what + "; " +
                      adapter_.name + " allows " + std::to_string(gl_int(l.query)) + " in a compute shader");
  }
  const bool from_spirv = spirv_shaders_ && replacement.empty();  // a replacement is GLSL
  const std::string_view spirv = from_spirv ? shader.source("spirv-gl") : std::string_view{};
  // No quiet fallback to GLSL: a test that asked for SPIR-V programs would pass on GLSL ones.
  if (from_spirv && spirv.empty())
    throw Error(ErrorKind::InvalidUsage, desc.name,
                "shader '" + std::string(shader.name) +
                    "' has no OpenGL SPIR-V translation (spirv-gl) to load; ASVGF_GL_SHADERS=glsl compiles its GLSL");
  const GLuint compute = glCreateShader(GL_COMPUTE_SHADER);
  if (from_spirv) {
    glShaderBinary(1, &compute, GL_SHADER_BINARY_FORMAT_SPIR_V_ARB, spirv.data(), static_cast<GLsizei>(spirv.size()));
    glSpecializeShaderARB(compute, "main", 0, nullptr, nullptr);
  } else {
    const GLchar* text = source.data();
    const auto length = static_cast<GLint>(source.size());
    glShaderSource(compute, 1, &text, &length);
    glCompileShader(compute);
  }
  auto log_of = [](GLuint object, bool program) {
    GLint size = 0;
    program ? glGetProgramiv(object, GL_INFO_LOG_LENGTH, &size) : glGetShaderiv(object, GL_INFO_LOG_LENGTH, &size);
    std::string log(static_cast<std::size_t>(std::max(size, 1)), '\0');
    program ? glGetProgramInfoLog(object, size, nullptr, log.data())
            : glGetShaderInfoLog(object, size, nullptr, log.data());
    return std::string(log.c_str());
  };
  GLint ok = 0;
  glGetShaderiv(compute, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    const std::string log = log_of(compute, false);
    glDeleteShader(compute);
    throw Error(ErrorKind::Backend, desc.name,
                "the GL compiler rejects shader '" + std::string(shader.name) + "': " + log);
  }
  PipelineObject object{desc.name, desc.shader, glCreateProgram()};
  glAttachShader(object.program, compute);
  if (program_dump_enabled()) glProgramParameteri(object.program, GL_PROGRAM_BINARY_RETRIEVABLE_HINT, GL_TRUE);
  glLinkProgram(object.program);
  glDeleteShader(compute);
  glGetProgramiv(object.program, GL_LINK_STATUS, &ok);
  if (!ok) {
    const std::string log = log_of(object.program, true);
    glDeleteProgram(object.program);
    throw Error(ErrorKind::Backend, desc.name,
                "the GL linker rejects shader '" + std::string(shader.name) + "': " + log);
  }
  dump_program(object.program, shader.name, source);
  return PipelineHandle{pipelines_.add(std::move(object))};
}

BindingSetHandle GlDevice::create_binding_set(const BindingSetDesc& desc) {
  const PipelineObject& pipeline = pipelines_.get(desc.pipeline.id, "pipeline");
  BindingSetObject object{desc.name, pipeline.shader, std::vector<Resource>(pipeline.shader->bindings.size())};
  for (const auto& entry : desc.entries) {
    const ShaderBinding* b = pipeline.shader->find(entry.name);
    if (!b) continue;
    // Storage usage is only a promise; binding for image load/store is where ES draws the line.
    if (b->kind == BindingKind::StorageImage && context_.flavour() == Flavour::Gles) {
      const ImageObject& image = images_.get(entry.resource.id, "image");
      if (!es_storage_format(image.desc.format))
        throw Error(ErrorKind::Unsupported, image.desc.name,
                    "format " + std::string(format_name(image.desc.format)) +
                        " is not an OpenGL ES 3.1 image load/store format (binding '" + entry.name + "' of set '" +
                        desc.name + "')");
    }
    object.bound[static_cast<std::size_t>(b - pipeline.shader->bindings.data())] = entry.resource;
  }
  return BindingSetHandle{binding_sets_.add(std::move(object))};
}

AccelHandle GlDevice::create_blas(const BlasDesc& desc) {
  throw Error(ErrorKind::Unsupported, desc.name, "OpenGL has no acceleration structures");
}
AccelHandle GlDevice::create_tlas(const TlasDesc& desc) {
  throw Error(ErrorKind::Unsupported, desc.name, "OpenGL has no acceleration structures");
}

TimerQueriesHandle GlDevice::create_timer_queries(const TimerQueriesDesc& desc) {
  make_current();
  TimerObject object{desc.name, std::vector<GLuint>(2 * desc.regions), std::vector<bool>(desc.regions)};
  if (capabilities_.timestamps) glGenQueries(static_cast<GLsizei>(object.queries.size()), object.queries.data());
  check_gl(desc.name, "glGenQueries");
  return TimerQueriesHandle{timers_.add(std::move(object))};
}

void GlDevice::destroy(BufferHandle h) {
  make_current();
  const auto b = buffers_.take(h.id, "buffer");
  glDeleteBuffers(1, &b.buffer);
}
void GlDevice::destroy(ImageHandle h) {
  make_current();
  const auto i = images_.take(h.id, "image");
  glDeleteTextures(1, &i.texture);
}
void GlDevice::destroy(PipelineHandle h) {
  make_current();
  glDeleteProgram(pipelines_.take(h.id, "pipeline").program);
}
void GlDevice::destroy(BindingSetHandle h) {
  binding_sets_.take(h.id, "binding set");
}
void GlDevice::destroy(AccelHandle) {
  throw Error(ErrorKind::InvalidHandle, "acceleration structure", "OpenGL has none");
}
void GlDevice::destroy(TimerQueriesHandle h) {
  make_current();
  auto t = timers_.take(h.id, "timer queries");
  if (capabilities_.timestamps) glDeleteQueries(static_cast<GLsizei>(t.queries.size()), t.queries.data());
}

void GlDevice::wait() {
  make_current();
  glFinish();
  check_gl(adapter_.name, "glFinish");
}

void GlDevice::upload_buffer(BufferHandle dst, std::uint64_t offset, std::span<const std::byte> data) {
  make_current();
  const BufferObject& b = buffers_.get(dst.id, "buffer");
  if (data.empty()) return;
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  glBindBuffer(GL_COPY_WRITE_BUFFER, b.buffer);
  glBufferSubData(GL_COPY_WRITE_BUFFER, static_cast<GLintptr>(offset), static_cast<GLsizeiptr>(data.size()),
                  data.data());
  glBindBuffer(GL_COPY_WRITE_BUFFER, 0);
  check_gl(b.desc.name, "upload_buffer");
}

void GlDevice::read_buffer(BufferHandle src, std::uint64_t offset, std::span<std::byte> out) {
  make_current();
  const BufferObject& b = buffers_.get(src.id, "buffer");
  if (out.empty()) return;
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  if (out.size() > readback_size_) {
    if (!readback_buffer_) glGenBuffers(1, &readback_buffer_);
    glBindBuffer(GL_COPY_WRITE_BUFFER, readback_buffer_);
    glBufferData(GL_COPY_WRITE_BUFFER, static_cast<GLsizeiptr>(out.size()), nullptr, GL_STREAM_READ);
    check_gl(b.desc.name, "read_buffer (readback buffer)");
    readback_size_ = out.size();
  }
  glBindBuffer(GL_COPY_READ_BUFFER, b.buffer);
  glBindBuffer(GL_COPY_WRITE_BUFFER, readback_buffer_);
  glCopyBufferSubData(GL_COPY_READ_BUFFER, GL_COPY_WRITE_BUFFER, static_cast<GLintptr>(offset), 0,
                      static_cast<GLsizeiptr>(out.size()));
  const void* mapped = glMapBufferRange(GL_COPY_WRITE_BUFFER, 0, static_cast<GLsizeiptr>(out.size()), GL_MAP_READ_BIT);
  if (mapped) std::memcpy(out.data(), mapped, out.size());
  if (mapped) glUnmapBuffer(GL_COPY_WRITE_BUFFER);
  glBindBuffer(GL_COPY_READ_BUFFER, 0);
  glBindBuffer(GL_COPY_WRITE_BUFFER, 0);
  check_gl(b.desc.name, "read_buffer");
  if (!mapped) throw Error(ErrorKind::Backend, b.desc.name, "glMapBufferRange returned nothing");
}

void GlDevice::upload_image(ImageHandle dst, std::span<const std::byte> data) {
  make_current();
  const ImageObject& i = images_.get(dst.id, "image");
  glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT);
  glBindTexture(GL_TEXTURE_2D, i.texture);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, static_cast<GLsizei>(i.desc.width), static_cast<GLsizei>(i.desc.height),
                  i.format.format, i.format.type, data.data());
  glBindTexture(GL_TEXTURE_2D, 0);
  check_gl(i.desc.name, "upload_image");
}

void GlDevice::read_image(ImageHandle src, std::span<std::byte> out) {
  make_current();
  const ImageObject& i = images_.get(src.id, "image");
  glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);
  read_texture(i, out.data());
  check_gl(i.desc.name, "read_image");
}

void GlDevice::read_texture(const ImageObject& image, void* destination) {
  if (context_.flavour() == Flavour::Gl) {
    glBindTexture(GL_TEXTURE_2D, image.texture);
    glGetTexImage(GL_TEXTURE_2D, 0, image.format.format, image.format.type, destination);
    glBindTexture(GL_TEXTURE_2D, 0);
    return;
  }
  // OpenGL ES has no glGetTexImage: read through a framebuffer.
  glBindFramebuffer(GL_READ_FRAMEBUFFER, read_framebuffer_);
  glFramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, image.texture, 0);
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glReadPixels(0, 0, static_cast<GLsizei>(image.desc.width), static_cast<GLsizei>(image.desc.height),
               image.format.format, image.format.type, destination);
  glFramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, 0, 0);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
}

std::vector<std::optional<double>> GlDevice::read_timers(TimerQueriesHandle handle) {
  make_current();
  TimerObject& t = timers_.get(handle.id, "timer queries");
  std::vector<std::optional<double>> times(t.written.size());
  if (!capabilities_.timestamps) return times;
  const bool es = context_.flavour() == Flavour::Gles;
  for (std::size_t r = 0; r < t.written.size(); ++r) {
    if (!t.written[r]) continue;
    GLuint64 begin = 0, end = 0;
    if (es) {
      glGetQueryObjectui64vEXT(t.queries[2 * r], GL_QUERY_RESULT, &begin);
      glGetQueryObjectui64vEXT(t.queries[2 * r + 1], GL_QUERY_RESULT, &end);
    } else {
      glGetQueryObjectui64v(t.queries[2 * r], GL_QUERY_RESULT, &begin);
      glGetQueryObjectui64v(t.queries[2 * r + 1], GL_QUERY_RESULT, &end);
    }
    if (end >= begin) times[r] = static_cast<double>(end - begin) * 1e-6;
  }
  check_gl(t.name, "read_timers");
  return times;
}

// ---- what replayed commands do -----------------------------------------------------------

void GlDevice::memory_barrier(State before, State after) {
  // Only shader writes are incoherent in GL; every other order is kept by the API.
  if (before != State::ShaderWrite) return;
  if (const GLbitfield bits = barrier_bits(after)) glMemoryBarrier(bits);
}

void GlDevice::dispatch(PipelineHandle pipeline_handle, BindingSetHandle set_handle,
                        const std::vector<std::byte>& uniforms, std::uint32_t x, std::uint32_t y, std::uint32_t z) {
  const PipelineObject& pipeline = pipelines_.get(pipeline_handle.id, "pipeline");
  const BindingSetObject& set = binding_sets_.get(set_handle.id, "binding set");
  glUseProgram(pipeline.program);
  const auto& bindings = pipeline.shader->bindings;
  for (std::size_t i = 0; i < bindings.size(); ++i) {
    const ShaderBinding& b = bindings[i];
    const GLuint unit = b.gl_binding;
    switch (b.kind) {
      case BindingKind::UniformBuffer:
        glBindBuffer(GL_UNIFORM_BUFFER, uniform_buffer_);
        glBufferData(GL_UNIFORM_BUFFER, static_cast<GLsizeiptr>(uniforms.size()), uniforms.data(), GL_STREAM_DRAW);
        glBindBufferBase(GL_UNIFORM_BUFFER, unit, uniform_buffer_);
        break;
      case BindingKind::StorageBuffer:
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, unit, buffers_.get(set.bound[i].id, "buffer").buffer);
        break;
      case BindingKind::SampledImage:
        glActiveTexture(GL_TEXTURE0 + unit);
        glBindTexture(GL_TEXTURE_2D, images_.get(set.bound[i].id, "image").texture);
        break;
      case BindingKind::StorageImage: {
        const ImageObject& image = images_.get(set.bound[i].id, "image");
        glBindImageTexture(unit, image.texture, 0, GL_FALSE, 0, image_access(b.access), image.format.internal);
        break;
      }
      case BindingKind::AccelerationStructure:
        break;  // refused at pipeline creation (no GLSL)
    }
  }
  glDispatchCompute(x, y, z);
  check_gl(pipeline.name, "glDispatchCompute");
}

void GlDevice::copy_buffer(const BufferCopy& copy) {
  glBindBuffer(GL_COPY_READ_BUFFER, buffers_.get(copy.src.id, "buffer").buffer);
  glBindBuffer(GL_COPY_WRITE_BUFFER, buffers_.get(copy.dst.id, "buffer").buffer);
  glCopyBufferSubData(GL_COPY_READ_BUFFER, GL_COPY_WRITE_BUFFER, static_cast<GLintptr>(copy.src_offset),
                      static_cast<GLintptr>(copy.dst_offset), static_cast<GLsizeiptr>(copy.size));
  glBindBuffer(GL_COPY_READ_BUFFER, 0);
  glBindBuffer(GL_COPY_WRITE_BUFFER, 0);
}

void GlDevice::copy_image(ImageHandle src, ImageHandle dst) {
  const ImageObject& s = images_.get(src.id, "image");
  const ImageObject& d = images_.get(dst.id, "image");
  glCopyImageSubData(s.texture, GL_TEXTURE_2D, 0, 0, 0, 0, d.texture, GL_TEXTURE_2D, 0, 0, 0, 0,
                     static_cast<GLsizei>(s.desc.width), static_cast<GLsizei>(s.desc.height), 1);
}

void GlDevice::copy_buffer_to_image(BufferHandle src, ImageHandle dst) {
  const ImageObject& i = images_.get(dst.id, "image");
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, buffers_.get(src.id, "buffer").buffer);
  glBindTexture(GL_TEXTURE_2D, i.texture);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, static_cast<GLsizei>(i.desc.width), static_cast<GLsizei>(i.desc.height),
                  i.format.format, i.format.type, nullptr);
  glBindTexture(GL_TEXTURE_2D, 0);
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
}

void GlDevice::copy_image_to_buffer(ImageHandle src, BufferHandle dst) {
  const ImageObject& i = images_.get(src.id, "image");
  glBindBuffer(GL_PIXEL_PACK_BUFFER, buffers_.get(dst.id, "buffer").buffer);
  read_texture(i, nullptr);  // offset 0 into the pack buffer
  glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
}

void GlDevice::clear_buffer(BufferHandle handle, std::uint32_t word) {
  const BufferObject& b = buffers_.get(handle.id, "buffer");
  // A dispatch on both flavours: ES has no buffer clear, and on desktop OpenGL a buffer filled by
  // glClearBufferSubData copied slower than one the dispatch filled (gpu_clear.hpp).
  gpu_clear().buffer(b.buffer, b.desc.size / 4, word);
  check_gl(b.desc.name, "clear_buffer");
}

GpuClear& GlDevice::gpu_clear() {
  if (!gpu_clear_) gpu_clear_ = std::make_unique<GpuClear>();
  return *gpu_clear_;
}

void GlDevice::clear_image(ImageHandle handle, std::array<float, 4> value) {
  const ImageObject& i = images_.get(handle.id, "image");
  if (options_.flavour == Flavour::Gl) {  // filled by the GPU, as clear_buffer
    const auto texel = texels_of(i.desc.format, value, 1);
    glClearTexImage(i.texture, 0, i.format.format, i.format.type, texel.data());
    return;
  }
  const bool cleared = gpu_clear().image(i.texture, i.format.internal, value);
  check_gl(i.desc.name, "clear_image");
  if (cleared) return;
  // Not colour-renderable in this ES context (e.g. float formats without GL_EXT_color_buffer_float).
  const auto texels = texels_of(i.desc.format, value, std::size_t{i.desc.width} * i.desc.height);
  glBindTexture(GL_TEXTURE_2D, i.texture);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, static_cast<GLsizei>(i.desc.width), static_cast<GLsizei>(i.desc.height),
                  i.format.format, i.format.type, texels.data());
  glBindTexture(GL_TEXTURE_2D, 0);
}

void GlDevice::timestamp(TimerQueriesHandle handle, std::uint32_t query) {
  TimerObject& t = timers_.get(handle.id, "timer queries");
  if (!capabilities_.timestamps) return;
  if (context_.flavour() == Flavour::Gles)
    glQueryCounterEXT(t.queries[query], GL_TIMESTAMP_EXT);
  else
    glQueryCounter(t.queries[query], GL_TIMESTAMP);
  if (query % 2 == 1) t.written[query / 2] = true;
}

std::unique_ptr<hal::Device> create_device(const DeviceOptions& options) {
  return std::make_unique<GlDevice>(options);
}

std::string environment_problem() {
  const std::string choice = shaders_variable();
  if (choice.empty() || choice == "glsl" || choice == "spirv") return "";
  return "ASVGF_GL_SHADERS is '" + choice + "'; valid: glsl, spirv";
}

}  // namespace hal::gl
