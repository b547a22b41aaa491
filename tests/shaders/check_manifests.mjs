// check_manifests.mjs SHADER_DIR VARIANT...: every variant CMake declared has a reflection JSON,
// and emitted every target it can: all seven without ray queries (OpenGL's SPIR-V among them),
// SPIR-V, HLSL and MSL with them (and then no WGSL, GLSL, ESSL or OpenGL SPIR-V). Every file a JSON lists exists.
import { existsSync, readFileSync } from 'node:fs';
import { join } from 'node:path';

const [dir, ...variants] = process.argv.slice(2);
const problems = [];
for (const variant of variants) {
  const path = join(dir, `${variant}.json`);
  if (!existsSync(path)) {
    problems.push(`${variant}: no ${variant}.json (not built?)`);
    continue;
  }
  const manifest = JSON.parse(readFileSync(path, 'utf8'));
  const emitted = Object.keys(manifest.targets).sort().join(' ');
  const want = manifest.uses_ray_query ? 'hlsl msl spv' : 'essl gl.spv glsl hlsl msl spv wgsl';
  if (emitted !== want) problems.push(`${variant}: emitted [${emitted}], expected [${want}]`);
  for (const file of Object.values(manifest.targets))
    if (!existsSync(join(dir, file))) problems.push(`${variant}: lists ${file}, which does not exist`);
  for (const [ext, why] of Object.entries(manifest.skipped_targets))
    if (existsSync(join(dir, `${variant}.${ext}`))) problems.push(`${variant}: skipped ${ext} (${why}) but the file exists`);
  console.log(`${variant}: ${emitted}${manifest.uses_ray_query ? ' (ray queries)' : ''}`);
}
for (const p of problems) console.log(`FAILED: ${p}`);
process.exit(problems.length ? 1 : 0);
