// manifold_chains.mjs — the three 24-step chains of relgeo_chain_benchmark
// with Manifold (npm package manifold-3d: its WebAssembly build under node,
// one thread; not a native peer, and its vertices are float32), as a second
// peer for time, face count, smallest angle and validity. Not part of the
// build or of CI: Manifold is not packaged for Debian.
//
//   mkdir -p /tmp/chains && build/benchmark/boolean/relgeo_chain_benchmark --export_chains=/tmp/chains
//   (cd /tmp/chains && npm install manifold-3d)
//   node benchmark/boolean/manifold_chains.mjs /tmp/chains
//
// Each chain runs 3 times, the operands' import included; the best time is
// printed, with the final mesh written as DIR/FAMILY_manifold.off (to check
// with relgeo's validation).
import fs from 'fs';
import path from 'path';
import { pathToFileURL } from 'url';

const dir = process.argv[2];
if (!dir) {
  console.error('usage: node manifold_chains.mjs DIR (the folder of relgeo_chain_benchmark --export_chains=DIR)');
  process.exit(2);
}
// manifold-3d installed in DIR (npm install there), loaded from it.
const entry = path.join(path.resolve(dir), 'node_modules', 'manifold-3d', 'manifold.js');
const { default: Module } = await import(pathToFileURL(entry).href);
const wasm = await Module();
wasm.setup();
const { Manifold, Mesh } = wasm;

function toManifold(m) {
  const mesh = new Mesh({ numProp: 3, vertProperties: new Float32Array(m.v), triVerts: new Uint32Array(m.f) });
  mesh.merge();
  return new Manifold(mesh);
}

// The smallest interior angle (degrees) and the faces with one under 1 degree.
function angles(mesh) {
  const p = mesh.vertProperties, t = mesh.triVerts, n = mesh.numProp;
  let smallest = 180, under1 = 0;
  for (let f = 0; f < t.length; f += 3) {
    let face = 180;
    for (let i = 0; i < 3; ++i) {
      const a = t[f + i] * n, b = t[f + (i + 1) % 3] * n, c = t[f + (i + 2) % 3] * n;
      const ux = p[b] - p[a], uy = p[b + 1] - p[a + 1], uz = p[b + 2] - p[a + 2];
      const vx = p[c] - p[a], vy = p[c + 1] - p[a + 1], vz = p[c + 2] - p[a + 2];
      const cross = Math.hypot(uy * vz - uz * vy, uz * vx - ux * vz, ux * vy - uy * vx);
      face = Math.min(face, Math.atan2(cross, ux * vx + uy * vy + uz * vz) * 180 / Math.PI);
    }
    smallest = Math.min(smallest, face);
    if (face < 1) ++under1;
  }
  return { smallest, under1 };
}

function writeOff(file, mesh) {
  const n = mesh.numProp, verts = mesh.vertProperties.length / n, faces = mesh.triVerts.length / 3;
  const lines = ['OFF', `${verts} ${faces} 0`];
  for (let v = 0; v < verts; ++v) lines.push(`${mesh.vertProperties[v * n]} ${mesh.vertProperties[v * n + 1]} ${mesh.vertProperties[v * n + 2]}`);
  for (let f = 0; f < faces; ++f) lines.push(`3 ${mesh.triVerts[3 * f]} ${mesh.triVerts[3 * f + 1]} ${mesh.triVerts[3 * f + 2]}`);
  fs.writeFileSync(file, lines.join('\n') + '\n');
}

for (const family of ['drilled_sphere', 'fused_spheres', 'slab_and_boxes']) {
  const chain = JSON.parse(fs.readFileSync(path.join(dir, family + '.json')));
  let best = Infinity, result = null;
  for (let run = 0; run < 3; ++run) {
    const start = process.hrtime.bigint();
    let current = toManifold(chain.start);
    for (const step of chain.steps) {
      const operand = toManifold(step.mesh);
      current = step.op === 'union' ? current.add(operand)
              : step.op === 'intersection' ? current.intersect(operand) : current.subtract(operand);
    }
    const mesh = current.getMesh();  // Manifold evaluates lazily: this runs the chain
    const seconds = Number(process.hrtime.bigint() - start) / 1e9;
    if (seconds < best) [best, result] = [seconds, mesh];
  }
  const { smallest, under1 } = angles(result);
  writeOff(path.join(dir, family + '_manifold.off'), result);
  console.log(`${family}: ${best.toFixed(3)} s, faces ${result.triVerts.length / 3}, ` +
              `smallest angle ${smallest.toExponential(2)} deg, under 1 degree ${under1}`);
}
