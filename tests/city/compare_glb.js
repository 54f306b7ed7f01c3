// A compressed glb (--compress) read by loaders.gl's GLTFLoader, whose own meshopt decoder
// undoes EXT_meshopt_compression, against the uncompressed glb of the same town:
//   node compare_glb.js PLAIN.glb COMPRESSED.glb
// - the documents alike but for buffers and buffer views: the same nodes, meshes, materials,
//   and accessors but for their bufferView and byteOffset;
// - every accessor decodes to the plain file's values: vertex and instance attributes element
//   for element, indices triangle for triangle (meshoptimizer's TRIANGLES mode may start a
//   triangle at another corner, keeping its winding, so each triangle is compared from its
//   smallest index);
// - every geometry view is compressed, into a fallback buffer without data, and a compressed
//   view holds at most 64 KiB of decoded bytes unless one accessor alone is larger (the chunks the
//   writer encodes as it goes; docs/export.md "Compression").
// Prints a summary line (views, compressed views, the most views of one kind); exits 1 with the
// failures listed.
'use strict';
const fs = require('fs');
const path = require('path');
const nm = path.join(__dirname, '../../tools/node/node_modules');
const {parse} = require(path.join(nm, '@loaders.gl/core'));
const {GLTFLoader, postProcessGLTF} = require(path.join(nm, '@loaders.gl/gltf'));

const [plainFile, packedFile] = process.argv.slice(2);
const failures = [];
const fail = (m) => failures.push(m);
const bytesOf = (file) => {
  const b = fs.readFileSync(file);
  return b.buffer.slice(b.byteOffset, b.byteOffset + b.byteLength);
};
const chunkBytes = 1 << 16;

async function read(file) {
  return postProcessGLTF(await parse(bytesOf(file), GLTFLoader, {gltf: {loadImages: false, decompressMeshes: true}}));
}

// The JSON's accessors without where they lie.
const placeless = (json) =>
  (json.accessors || []).map((a) => {
    const {bufferView, byteOffset, ...rest} = a;
    return JSON.stringify(rest);
  });

function triangles(values) {
  const out = [];
  for (let t = 0; t + 2 < values.length; t += 3) {
    let a = [values[t], values[t + 1], values[t + 2]];
    while (a[0] !== Math.min(...a)) a = [a[1], a[2], a[0]];
    out.push(a.join(','));
  }
  return out.sort();
}

(async () => {
  const plainJson = JSON.parse(readJsonChunk(plainFile)), packedJson = JSON.parse(readJsonChunk(packedFile));
  for (const key of ['nodes', 'meshes', 'materials', 'scenes', 'images', 'textures'])
    if (JSON.stringify(plainJson[key]) !== JSON.stringify(packedJson[key])) fail(`${key} differ`);
  const pa = placeless(plainJson), ca = placeless(packedJson);
  if (pa.length !== ca.length) fail(`${pa.length} accessors against ${ca.length}`);
  for (let i = 0; i < Math.min(pa.length, ca.length); ++i) if (pa[i] !== ca[i]) fail(`accessor ${i}: ${pa[i]} against ${ca[i]}`);

  // The views: images plain, geometry compressed into the fallback buffer, chunks bounded.
  const fallback = (packedJson.buffers || []).findIndex((b) => b.extensions && b.extensions.EXT_meshopt_compression && b.extensions.EXT_meshopt_compression.fallback);
  if (fallback < 0 || packedJson.buffers[fallback].uri !== undefined) fail('no fallback buffer without data');
  if (!(packedJson.extensionsRequired || []).includes('EXT_meshopt_compression')) fail('EXT_meshopt_compression not required');
  const imageViews = new Set((packedJson.images || []).map((im) => im.bufferView));
  const accessorsOf = new Map();
  (packedJson.accessors || []).forEach((a) => accessorsOf.set(a.bufferView, (accessorsOf.get(a.bufferView) || 0) + 1));
  let compressed = 0;
  const perKind = new Map();
  packedJson.bufferViews.forEach((v, i) => {
    const e = v.extensions && v.extensions.EXT_meshopt_compression;
    if (imageViews.has(i)) {
      if (e) fail(`image view ${i} compressed`);
      return;
    }
    if (!e) return fail(`view ${i} not compressed`);
    ++compressed;
    if (v.buffer !== fallback) fail(`view ${i} not in the fallback buffer`);
    if (e.count * e.byteStride !== v.byteLength) fail(`view ${i}: count × byteStride is not its byteLength`);
    if (v.byteLength > chunkBytes && accessorsOf.get(i) !== 1) fail(`view ${i}: ${v.byteLength} bytes for ${accessorsOf.get(i)} accessors`);
    const kind = `${e.mode} ${e.byteStride} ${v.target || 0}`;
    perKind.set(kind, (perKind.get(kind) || 0) + 1);
  });

  // Every accessor's values, decoded by loaders.gl, against the plain file's.
  const plain = await read(plainFile), packed = await read(packedFile);
  const indexAccessors = new Set();
  for (const m of plainJson.meshes || []) for (const p of m.primitives) if (p.indices !== undefined) indexAccessors.add(p.indices);
  let values = 0;
  for (let i = 0; i < Math.min(plain.accessors.length, packed.accessors.length); ++i) {
    const a = plain.accessors[i].value, b = packed.accessors[i].value;
    if (!a || !b || a.length !== b.length) {
      fail(`accessor ${i}: ${a && a.length} values against ${b && b.length}`);
      continue;
    }
    values += a.length;
    if (indexAccessors.has(i)) {
      const ta = triangles(a), tb = triangles(b);
      if (ta.some((t, k) => t !== tb[k])) fail(`accessor ${i}: other triangles`);
    } else {
      for (let k = 0; k < a.length; ++k)
        if (a[k] !== b[k] && !(Number.isNaN(a[k]) && Number.isNaN(b[k]))) {
          fail(`accessor ${i}: value ${k} is ${b[k]}, not ${a[k]}`);
          break;
        }
    }
  }
  const most = Math.max(0, ...perKind.values());
  console.log(`${path.basename(packedFile)}: ${packedJson.bufferViews.length} views, ${compressed} compressed, at most ${most} of one kind; ${values} values alike`);
  if (failures.length) {
    for (const f of failures.slice(0, 20)) console.log(`  ${f}`);
    process.exit(1);
  }
  if (process.env.MIN_VIEWS_OF_A_KIND && most < Number(process.env.MIN_VIEWS_OF_A_KIND)) {
    console.log(`  at most ${most} views of one kind: the chunks are not exercised`);
    process.exit(1);
  }
})().catch((e) => {
  console.error(e);
  process.exit(2);
});

function readJsonChunk(file) {
  const b = fs.readFileSync(file);
  if (b.readUInt32LE(0) !== 0x46546c67 || b.readUInt32LE(16) !== 0x4e4f534a) throw new Error(`${file}: not a glb`);
  return b.toString('utf8', 20, 20 + b.readUInt32LE(12));
}
