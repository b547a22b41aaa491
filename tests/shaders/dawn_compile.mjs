// dawn_compile.mjs NODE_MODULES FILE.wgsl...: compiles each WGSL file into a compute pipeline in
// Dawn (npm webgpu, pinned in tools/package.json; lavapipe on CI) and fails on any error or
// warning from getCompilationInfo, an error scope or an uncaptured error.
import { readFileSync } from 'node:fs';
import { basename, join } from 'node:path';
import { pathToFileURL } from 'node:url';

const [nodeModules, ...files] = process.argv.slice(2);
if (files.length === 0) {
  console.error('usage: node dawn_compile.mjs NODE_MODULES FILE.wgsl...');
  process.exit(2);
}
const { create, globals } = await import(pathToFileURL(join(nodeModules, 'webgpu', 'index.js')).href);
Object.assign(globalThis, globals);

const gpu = create([]);
const adapter = await gpu.requestAdapter();
if (!adapter) {
  console.error('dawn_compile: no WebGPU adapter (is a Vulkan driver such as lavapipe installed?)');
  process.exit(1);
}
const device = await adapter.requestDevice();
const uncaptured = [];
device.addEventListener('uncapturederror', (event) => uncaptured.push(event.error.message));

let failed = false;
for (const file of files) {
  const problems = [];
  device.pushErrorScope('internal');
  device.pushErrorScope('validation');
  const module = device.createShaderModule({ label: basename(file), code: readFileSync(file, 'utf8') });
  const info = await module.getCompilationInfo();
  for (const m of info.messages)
    if (m.type === 'error' || m.type === 'warning') problems.push(`${m.type} at ${m.lineNum}:${m.linePos}: ${m.message}`);
  try {
    await device.createComputePipelineAsync({ layout: 'auto', compute: { module, entryPoint: 'main' } });
  } catch (error) {
    problems.push(`pipeline: ${error.message}`);
  }
  for (const scope of ['validation', 'internal']) {
    const error = await device.popErrorScope();
    if (error) problems.push(`${scope} error: ${error.message}`);
  }
  problems.push(...uncaptured.splice(0));
  if (problems.length) {
    failed = true;
    console.log(`FAILED: ${basename(file)}\n  ${problems.join('\n  ')}`);
  } else {
    console.log(`ok: ${basename(file)}`);
  }
}
device.destroy();
process.exit(failed ? 1 : 0);
