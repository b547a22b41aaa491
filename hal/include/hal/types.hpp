// hal/types.hpp: handles, formats, resource states and the value-type descriptors of HAL objects.
//
// Ownership: a Device owns every object it creates. Objects are named by small typed handles that
// are cheap to copy; `Device::destroy(handle)` releases one. Using a handle after destroy is an
// error the device reports (hal::Error of kind InvalidHandle; the recording HAL also logs it).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace hal {

// ---- Handles --------------------------------------------------------------------------------
// id 0 is never a valid object, so a default-constructed handle is "none".
#define HAL_DEFINE_HANDLE(Name)                        \
  struct Name {                                        \
    std::uint32_t id = 0;                              \
    explicit operator bool() const { return id != 0; } \
    friend bool operator==(Name, Name) = default;      \
  }
HAL_DEFINE_HANDLE(BufferHandle);
HAL_DEFINE_HANDLE(ImageHandle);
HAL_DEFINE_HANDLE(PipelineHandle);
HAL_DEFINE_HANDLE(BindingSetHandle);
HAL_DEFINE_HANDLE(AccelHandle);
HAL_DEFINE_HANDLE(TimerQueriesHandle);
#undef HAL_DEFINE_HANDLE

// A buffer, image or acceleration structure, as named in barriers and binding sets.
enum class ResourceKind : std::uint8_t { Buffer, Image, Accel };
struct Resource {
  ResourceKind kind = ResourceKind::Buffer;
  std::uint32_t id = 0;
  Resource() = default;
  Resource(BufferHandle h) : kind(ResourceKind::Buffer), id(h.id) {}  // NOLINT: implicit on purpose
  Resource(ImageHandle h) : kind(ResourceKind::Image), id(h.id) {}    // NOLINT
  Resource(AccelHandle h) : kind(ResourceKind::Accel), id(h.id) {}    // NOLINT
  friend bool operator==(Resource, Resource) = default;
};

// ---- Formats --------------------------------------------------------------------------------
// Every format the HAL exposes. All are valid for sampled reads and storage writes on Vulkan 1.3
// devices that report them (queried at image creation; unsupported ones throw Unsupported).
enum class Format : std::uint8_t {
  Undefined,
  R8Unorm,
  RGBA8Unorm,
  R16F,
  RG16F,
  RGBA16F,
  R32F,
  RG32F,
  RGBA32F,
  R32Uint,
  RG32Uint,
  RGBA32Uint,
  RGBA16Uint,
};
inline constexpr std::array kAllFormats = {Format::R8Unorm, Format::RGBA8Unorm, Format::R16F,       Format::RG16F,
                                           Format::RGBA16F, Format::R32F,       Format::RG32F,      Format::RGBA32F,
                                           Format::R32Uint, Format::RG32Uint,   Format::RGBA32Uint, Format::RGBA16Uint};

// Bytes per texel; 0 for Undefined.
std::uint32_t format_size(Format format);
// Channels per texel; 0 for Undefined.
std::uint32_t format_channels(Format format);
// GLSL image format qualifier ("rgba16f", ...), as written in shaders and their reflection.
std::string_view format_name(Format format);
// Unsigned integer texels (r32ui, rg32ui, rgba32ui, rgba16ui): cleared and read as integers.
bool format_is_uint(Format format);
// Inverse of format_name; Format::Undefined when the name is unknown.
Format format_from_name(std::string_view name);

// ---- Resource states ------------------------------------------------------------------------
// The small set of states a barrier moves a resource between (as in wgpu-hal). A new resource
// starts Undefined: a barrier from Undefined discards the contents.
enum class State : std::uint8_t {
  Undefined,
  ShaderRead,       // read by dispatches (sampled image, readonly storage, uniform)
  ShaderWrite,      // written (or read and written) by dispatches
  CopySrc,          // source of copies and of host readback
  CopyDst,          // destination of copies, clears and host uploads
  AccelBuildInput,  // vertex/index buffers read by an acceleration-structure build
  AccelWrite,       // acceleration structure being built
  AccelRead,        // acceleration structure traced against (or used as a TLAS build input)
  Present,          // handed to the presentation engine
};
std::string_view to_string(State state);

// ---- Usage flags ----------------------------------------------------------------------------
enum class BufferUsage : std::uint32_t {
  None = 0,
  Uniform = 1u << 0,
  Storage = 1u << 1,
  CopySrc = 1u << 2,
  CopyDst = 1u << 3,
  AccelBuildInput = 1u << 4,  // vertex/index data of a bottom-level acceleration structure
};
enum class ImageUsage : std::uint32_t {
  None = 0,
  Sampled = 1u << 0,  // texelFetch through texture2D
  Storage = 1u << 1,  // imageLoad/imageStore
  CopySrc = 1u << 2,
  CopyDst = 1u << 3,
};
template <typename E>
concept UsageFlags = std::is_same_v<E, BufferUsage> || std::is_same_v<E, ImageUsage>;
template <UsageFlags E>
constexpr E operator|(E a, E b) {
  return static_cast<E>(static_cast<std::uint32_t>(a) | static_cast<std::uint32_t>(b));
}
template <UsageFlags E>
constexpr bool has(E set, E flag) {
  return (static_cast<std::uint32_t>(set) & static_cast<std::uint32_t>(flag)) != 0;
}

// ---- Descriptors ----------------------------------------------------------------------------
// Every object carries a debug name: errors, logs, validation messages and captures use it.
struct BufferDesc {
  std::string name;
  std::uint64_t size = 0;  // bytes, > 0
  BufferUsage usage = BufferUsage::Storage;
};

struct ImageDesc {
  std::string name;
  std::uint32_t width = 0;  // texels, >= 1 and <= Capabilities::max_image_dimension
  std::uint32_t height = 0;
  Format format = Format::Undefined;
  ImageUsage usage = ImageUsage::Sampled | ImageUsage::Storage;
};

// What a bottom-level acceleration structure holds.
//   Triangles: the traversal tests the triangles itself (fast on ray-tracing hardware).
//   Boxes:     procedural primitives; the traversal reports every box the ray passes through as a
//              candidate and the shader decides the hit (ray queries: rayQueryGenerateIntersectionEXT).
//              Lets a shader apply its own intersection test, e.g. one shared with a software path.
enum class BlasGeometry : std::uint8_t { Triangles, Boxes };

// Triangles: float3 positions (12-byte stride) and uint32 indices, three per triangle.
// Boxes: `boxes` holds box_count boxes as float3 min, float3 max (24-byte stride); the primitive
// index a ray query reports is the box's position in that buffer.
// The input buffers need BufferUsage::AccelBuildInput.
struct BlasDesc {
  std::string name;
  BufferHandle vertices;
  std::uint32_t vertex_count = 0;
  BufferHandle indices;
  std::uint32_t triangle_count = 0;
  bool allow_update = false;  // refit in place later (build(update=true)) instead of rebuilding
  BlasGeometry geometry = BlasGeometry::Triangles;
  BufferHandle boxes;
  std::uint32_t box_count = 0;

  static BlasDesc of_boxes(std::string name, BufferHandle boxes, std::uint32_t box_count, bool allow_update = false) {
    BlasDesc d;
    d.name = std::move(name);
    d.allow_update = allow_update;
    d.geometry = BlasGeometry::Boxes;
    d.boxes = boxes;
    d.box_count = box_count;
    return d;
  }
  std::uint32_t primitive_count() const { return geometry == BlasGeometry::Boxes ? box_count : triangle_count; }
};

// One instance of a top-level acceleration structure.
struct TlasInstance {
  AccelHandle blas;
  std::array<float, 12> transform{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};  // row-major 3x4, object->world
  std::uint32_t custom_index = 0;                                       // gl_InstanceCustomIndex, 24 bits
  std::uint8_t mask = 0xff;
};

struct TlasDesc {
  std::string name;
  std::uint32_t max_instances = 0;
  bool allow_update = false;
};

struct TimerQueriesDesc {
  std::string name;
  std::uint32_t regions = 0;  // each region is a begin/end timestamp pair
};

}  // namespace hal
