// webgpu_server.mjs NODE_MODULES SHADER_DIR: the Node half of the test-only WebGPU backend
// (tests/wgsl/dawn_device.cpp). It runs the shader tool's WGSL in Dawn (npm `webgpu`, pinned in
// tools/package.json; lavapipe underneath) for a C++ process that talks to it over stdin/stdout.
//
// Protocol, one request at a time: a line of JSON {"op": ..., "bytes": N?, ...} followed by N raw
// bytes when "bytes" is given; the reply is a line of JSON {"ok": true, "bytes": N?, ...} followed by
// N raw bytes, or {"ok": false, "error": "..."}. Ops: hello, create_buffer, create_image,
// create_pipeline, create_binding_set, destroy, upload_buffer, upload_image, read_buffer, read_image,
// submit (a list of recorded commands), wait. Validation errors Dawn reported since the last reply
// come back in the reply's "errors" list. WEBGPU_SERVER_LOG=1 logs each request to stderr.
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { pathToFileURL } from 'node:url';

const [nodeModules, shaderDir] = process.argv.slice(2);
const { create, globals } = await import(pathToFileURL(join(nodeModules, 'webgpu', 'index.js')).href);
Object.assign(globalThis, globals);

// HAL format name (hal::format_name) -> WebGPU format and bytes per texel.
const FORMATS = {
  r8: ['r8unorm', 1], rgba8: ['rgba8unorm', 4], r16f: ['r16float', 2], rg16f: ['rg16float', 4],
  rgba16f: ['rgba16float', 8], r32f: ['r32float', 4], rg32f: ['rg32float', 8], rgba32f: ['rgba32float', 16],
  r32ui: ['r32uint', 4], rg32ui: ['rg32uint', 8], rgba32ui: ['rgba32uint', 16], rgba16ui: ['rgba16uint', 8],
};

const gpu = create([]);
globalThis.webgpuInstance = gpu;  // kept reachable: collecting it destroys Dawn's instance under the device
const adapter = await gpu.requestAdapter();
if (!adapter) {
  process.stderr.write('webgpu_server: no WebGPU adapter (is a Vulkan driver such as lavapipe installed?)\n');
  process.exit(1);
}
const device = await adapter.requestDevice({
  requiredLimits: {
    maxStorageBuffersPerShaderStage: adapter.limits.maxStorageBuffersPerShaderStage,
    maxStorageTexturesPerShaderStage: adapter.limits.maxStorageTexturesPerShaderStage,
    maxStorageBufferBindingSize: adapter.limits.maxStorageBufferBindingSize,
    maxBufferSize: adapter.limits.maxBufferSize,
  },
});
const errors = [];
device.addEventListener('uncapturederror', (event) => errors.push(event.error.message));

const buffers = new Map(), images = new Map(), pipelines = new Map(), sets = new Map(), modules = new Map();
const align4 = (n) => Math.ceil(n / 4) * 4;

function half(f) {  // float -> fp16 bits, round to nearest even
  const view = new DataView(new ArrayBuffer(4));
  view.setFloat32(0, f);
  const x = view.getUint32(0), sign = (x >>> 16) & 0x8000, abs = x & 0x7fffffff;
  if (abs >= 0x7f800000) return sign | 0x7c00 | (abs > 0x7f800000 ? 0x200 : 0);
  if (abs >= 0x477ff000) return sign | 0x7c00;
  if (abs < 0x38800000) {
    view.setUint32(0, abs);
    return sign | Math.round(view.getFloat32(0) * 16777216);
  }
  return sign | ((abs + 0xfff + ((abs >>> 13) & 1) - 0x38000000) >>> 13);
}

// One texel of `value` (4 floats) in the image's format.
function texel(format, value) {
  const [, size] = FORMATS[format];
  const out = Buffer.alloc(size);
  const channels = { r8: 1, rgba8: 4, r16f: 1, rg16f: 2, rgba16f: 4, r32f: 1, rg32f: 2, rgba32f: 4, r32ui: 1, rg32ui: 2, rgba32ui: 4, rgba16ui: 4 }[format];
  for (let c = 0; c < channels; ++c) {
    const v = value[c];
    if (format.endsWith('8')) out.writeUInt8(Math.round(Math.min(1, Math.max(0, v)) * 255), c);
    else if (format.endsWith('16f')) out.writeUInt16LE(half(v), 2 * c);
    else if (format.endsWith('32f')) out.writeFloatLE(v, 4 * c);
    else if (format === 'rgba16ui') out.writeUInt16LE(Math.min(65535, Math.max(0, v)) >>> 0, 2 * c);
    else out.writeUInt32LE(v >>> 0, 4 * c);
  }
  return out;
}

function staging(bytes) {  // a COPY_SRC buffer holding `bytes`
  const buffer = device.createBuffer({ size: align4(bytes.length), usage: GPUBufferUsage.COPY_SRC, mappedAtCreation: true });
  new Uint8Array(buffer.getMappedRange()).set(bytes);
  buffer.unmap();
  return buffer;
}

// Tightly packed rows need no 256-byte row pitch when each copy is one row.
function rowsBufferToImage(encoder, buffer, image) {
  const row = image.width * FORMATS[image.format][1];
  for (let y = 0; y < image.height; ++y)
    encoder.copyBufferToTexture({ buffer, offset: y * row }, { texture: image.texture, origin: { x: 0, y } }, { width: image.width, height: 1 });
}
function rowsImageToBuffer(encoder, image, buffer) {
  const row = image.width * FORMATS[image.format][1];
  for (let y = 0; y < image.height; ++y)
    encoder.copyTextureToBuffer({ texture: image.texture, origin: { x: 0, y } }, { buffer, offset: y * row }, { width: image.width, height: 1 });
}

function module(shader) {
  if (!modules.has(shader)) modules.set(shader, device.createShaderModule({ label: shader, code: readFileSync(join(shaderDir, shader + '.wgsl'), 'utf8') }));
  return modules.get(shader);
}

function bindGroups(set, uniforms) {
  const { pipeline } = pipelines.get(set.pipeline);
  const byGroup = new Map();
  const add = (group, entry) => (byGroup.get(group) ?? byGroup.set(group, []).get(group)).push(entry);
  for (const e of set.entries) {
    let resource;
    if (e.resource === 'buffer') resource = { buffer: buffers.get(e.id).buffer };
    else resource = images.get(e.id).texture.createView();
    add(e.group, { binding: e.binding, resource });
  }
  if (uniforms) add(uniforms.group, { binding: uniforms.binding, resource: { buffer: uniforms.buffer } });
  return [...byGroup].map(([group, entries]) => [group, device.createBindGroup({ layout: pipeline.getBindGroupLayout(group), entries })]);
}

async function submit(ops) {
  const encoder = device.createCommandEncoder();
  const temporary = [];
  for (const op of ops) {
    if (op.op === 'dispatch') {
      const set = sets.get(op.set);
      let uniforms = null;
      if (op.uniforms) {
        const bytes = Buffer.from(op.uniforms, 'base64');
        const buffer = device.createBuffer({ size: align4(bytes.length), usage: GPUBufferUsage.UNIFORM, mappedAtCreation: true });
        new Uint8Array(buffer.getMappedRange()).set(bytes);
        buffer.unmap();
        temporary.push(buffer);
        uniforms = { group: op.uniform_group, binding: op.uniform_binding, buffer };
      }
      const pass = encoder.beginComputePass({ label: op.label });
      pass.setPipeline(pipelines.get(set.pipeline).pipeline);
      for (const [group, bindGroup] of bindGroups(set, uniforms)) pass.setBindGroup(group, bindGroup);
      pass.dispatchWorkgroups(op.x, op.y, op.z);
      pass.end();
    } else if (op.op === 'copy_buffer') {
      encoder.copyBufferToBuffer(buffers.get(op.src).buffer, op.src_offset, buffers.get(op.dst).buffer, op.dst_offset, op.size);
    } else if (op.op === 'copy_image') {
      const src = images.get(op.src), dst = images.get(op.dst);
      encoder.copyTextureToTexture({ texture: src.texture }, { texture: dst.texture }, { width: src.width, height: src.height });
    } else if (op.op === 'copy_buffer_to_image') {
      rowsBufferToImage(encoder, buffers.get(op.src).buffer, images.get(op.dst));
    } else if (op.op === 'copy_image_to_buffer') {
      rowsImageToBuffer(encoder, images.get(op.src), buffers.get(op.dst).buffer);
    } else if (op.op === 'clear_buffer') {
      const b = buffers.get(op.id);
      const bytes = Buffer.alloc(b.size);
      for (let i = 0; i + 4 <= bytes.length; i += 4) bytes.writeUInt32LE(op.word >>> 0, i);
      const s = staging(bytes);
      temporary.push(s);
      encoder.copyBufferToBuffer(s, 0, b.buffer, 0, b.size);
    } else if (op.op === 'clear_image') {
      const image = images.get(op.id);
      const one = texel(image.format, op.value);
      const s = staging(Buffer.concat(Array(image.width * image.height).fill(one)));
      temporary.push(s);
      rowsBufferToImage(encoder, s, image);
    } else {
      throw new Error('unknown command ' + op.op);
    }
  }
  device.queue.submit([encoder.finish()]);
  await device.queue.onSubmittedWorkDone();
  for (const b of temporary) b.destroy();
}

async function readBack(size, record) {
  const buffer = device.createBuffer({ size: align4(size), usage: GPUBufferUsage.COPY_DST | GPUBufferUsage.MAP_READ });
  const encoder = device.createCommandEncoder();
  record(encoder, buffer);
  device.queue.submit([encoder.finish()]);
  await buffer.mapAsync(GPUMapMode.READ);
  const bytes = Buffer.from(new Uint8Array(buffer.getMappedRange()).slice(0, size));
  buffer.unmap();
  buffer.destroy();
  return bytes;
}

async function handle(request, payload) {
  switch (request.op) {
    case 'hello': {
      const info = adapter.info ?? {};
      return { adapter: `${info.description || info.device || 'WebGPU adapter'} (${info.vendor || 'unknown vendor'}, Dawn)`, architecture: info.architecture ?? '', limits: {
        maxTextureDimension2D: device.limits.maxTextureDimension2D, maxStorageBufferBindingSize: device.limits.maxStorageBufferBindingSize,
        maxBufferSize: device.limits.maxBufferSize } };
    }
    case 'create_buffer':
      buffers.set(request.id, { size: align4(request.size), buffer: device.createBuffer({ label: request.name, size: align4(request.size),
        usage: GPUBufferUsage.STORAGE | GPUBufferUsage.COPY_SRC | GPUBufferUsage.COPY_DST }) });
      return {};
    case 'create_image': {
      const [format] = FORMATS[request.format];
      let usage = GPUTextureUsage.TEXTURE_BINDING | GPUTextureUsage.COPY_SRC | GPUTextureUsage.COPY_DST;
      if (request.storage) usage |= GPUTextureUsage.STORAGE_BINDING;
      images.set(request.id, { format: request.format, width: request.width, height: request.height,
        texture: device.createTexture({ label: request.name, size: [request.width, request.height], format, usage }) });
      return {};
    }
    case 'create_pipeline':
      pipelines.set(request.id, { shader: request.shader, pipeline: device.createComputePipeline({ label: request.name, layout: 'auto',
        compute: { module: module(request.shader), entryPoint: 'main' } }) });
      return {};
    case 'create_binding_set':
      sets.set(request.id, { pipeline: request.pipeline, entries: request.entries });
      return {};
    case 'destroy': {
      const table = { buffer: buffers, image: images, pipeline: pipelines, binding_set: sets }[request.kind];
      const object = table.get(request.id);
      if (request.kind === 'buffer') object.buffer.destroy();
      if (request.kind === 'image') object.texture.destroy();
      table.delete(request.id);
      return {};
    }
    case 'upload_buffer': {
      const padded = Buffer.alloc(align4(payload.length));
      payload.copy(padded);
      device.queue.writeBuffer(buffers.get(request.id).buffer, request.offset, padded);
      return {};
    }
    case 'upload_image': {
      const image = images.get(request.id);
      device.queue.writeTexture({ texture: image.texture }, payload, { bytesPerRow: image.width * FORMATS[image.format][1] },
        { width: image.width, height: image.height });
      return {};
    }
    case 'read_buffer': {
      const b = buffers.get(request.id);
      const start = request.offset - (request.offset % 4);
      const bytes = await readBack(align4(request.offset + request.size) - start,
        (encoder, dst) => encoder.copyBufferToBuffer(b.buffer, start, dst, 0, align4(request.offset + request.size) - start));
      return { payload: bytes.subarray(request.offset - start, request.offset - start + request.size) };
    }
    case 'read_image': {
      const image = images.get(request.id);
      return { payload: await readBack(image.width * image.height * FORMATS[image.format][1], (encoder, dst) => rowsImageToBuffer(encoder, image, dst)) };
    }
    case 'submit':
      await submit(request.ops);
      return {};
    case 'wait':
      await device.queue.onSubmittedWorkDone();
      return {};
    default:
      throw new Error('unknown op ' + request.op);
  }
}

function reply(object, payload) {
  const header = JSON.stringify(payload ? { ...object, bytes: payload.length } : object) + '\n';
  process.stdout.write(payload ? Buffer.concat([Buffer.from(header), payload]) : header);
}

// Requests arrive as a byte stream: split it into (JSON line, payload) pairs and run them in order.
let pending = Buffer.alloc(0);
let chain = Promise.resolve();
process.stdin.on('data', (chunk) => {
  pending = Buffer.concat([pending, chunk]);
  for (;;) {
    const newline = pending.indexOf(10);
    if (newline < 0) return;
    const request = JSON.parse(pending.subarray(0, newline).toString('utf8'));
    if (process.env.WEBGPU_SERVER_LOG) process.stderr.write('request: ' + JSON.stringify(request).slice(0, 300) + '\n');
    const size = request.bytes ?? 0;
    if (pending.length < newline + 1 + size) return;
    const payload = Buffer.from(pending.subarray(newline + 1, newline + 1 + size));
    pending = pending.subarray(newline + 1 + size);
    // Errors come from the device's uncaptured-error events; one arriving late is reported with a
    // later request, which still fails the test.
    chain = chain.then(async () => {
      try {
        const result = await handle(request, payload);
        const found = errors.splice(0);
        const { payload: out, ...rest } = result;
        reply({ ok: true, ...rest, ...(found.length ? { errors: found } : {}) }, out);
      } catch (error) {
        reply({ ok: false, error: `${request.op}: ${error.message}` });
      }
    });
  }
});
process.stdin.on('end', () => chain.then(() => { device.destroy(); process.exit(0); }));
