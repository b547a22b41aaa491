// naga_to_wgsl.mjs NODE_MODULES IN.spv OUT.wgsl: translates SPIR-V to WGSL with naga (npm
// naga-wasm, pinned in tools/package.json). asvgf_shaderc runs it once per variant without ray
// queries. Exit 1 with naga's report on failure.
import { readFileSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { pathToFileURL } from 'node:url';

const [nodeModules, input, output] = process.argv.slice(2);
if (!output) {
  console.error('usage: node naga_to_wgsl.mjs NODE_MODULES IN.spv OUT.wgsl');
  process.exit(2);
}
// Imported by path: this script lives outside tools/node_modules' resolution scope.
const naga = await import(pathToFileURL(join(nodeModules, 'naga-wasm', 'dist', 'node.js')).href);

const bytes = readFileSync(input);
const words = new Uint32Array(bytes.buffer, bytes.byteOffset, bytes.byteLength / 4);
let module, info;
try {
  module = naga.parseSpirv(words);
  info = naga.validate(module);
  writeFileSync(output, naga.writeWgsl(module, info));
} catch (error) {
  const text = error instanceof naga.NagaError ? `${error.kind}: ${error.formatted}` : String(error?.stack ?? error);
  console.error(`naga ${naga.nagaVersion ?? ''}: ${text}`);
  process.exit(1);
} finally {
  info?.free();
  module?.free();
}
