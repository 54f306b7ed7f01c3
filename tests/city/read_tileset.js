// Reads a tileset as a 3D Tiles client does (loaders.gl's Tiles3DLoader and GLTFLoader) and
// checks it against oracles of its own:
//   node read_tileset.js TILESET_DIR LON LAT HEIGHT WHOLE.glb R
// - the root transform is the east-north-up frame at (LON, LAT, HEIGHT) on WGS 84, by the
//   ellipsoid's formulas written out here (not PROJ, which wrote it);
// - every tile's content lies inside its bounding volume, every child's volume inside its
//   parent's, geometric errors fall from parent to child and a leaf's is 0; refinement REPLACE;
// - a block tile's error is at least the height of each of its blocks, and its blocks are as
//   many as the buildings of the tile that refines it;
// - the leaves' triangles add up to WHOLE.glb's (the same town written as one glb), and every
//   building of WHOLE.glb is in exactly one leaf tile;
// - a merged tileset (no root transform): each part's root transform a rigid motion;
// - each building lands on the globe where the footprint file puts it: its surface's centroid
//   in WHOLE.glb (the file's equirectangular frame about LON, LAT on the sphere of radius R, taken
//   back to lon/lat by that projection's formulas) against the same centroid in its tile, placed by
//   the tiles' transforms. Allowed: the frame's own stretch against WGS 84 over the distance d
//   from the tile's origin, |N/R - 1| + |M/R - 1| + 1e-3 (N, M the ellipsoid's radii of
//   curvature; 1e-3 bounds the frame's reported scale_error), times d, plus the tangent plane's
//   drop d^2 / (2 R), plus 2 mm of quantization.
// Prints a summary line; exits 1 with the failures listed.
'use strict';
const fs = require('fs');
const path = require('path');
const nm = path.join(__dirname, '../../tools/node/node_modules');
const {parse} = require(path.join(nm, '@loaders.gl/core'));
const {Tiles3DLoader} = require(path.join(nm, '@loaders.gl/3d-tiles'));
const {GLTFLoader, postProcessGLTF} = require(path.join(nm, '@loaders.gl/gltf'));

const [dir, lonArg, latArg, heightArg, wholeGlb, radiusArg] = process.argv.slice(2);
const failures = [];
// A file's bytes as an ArrayBuffer of their own (a small Buffer shares Node's pool).
const bytesOf = (file) => {
  const b = fs.readFileSync(file);
  return b.buffer.slice(b.byteOffset, b.byteOffset + b.byteLength);
};
const fail = (m) => failures.push(m);

// The ECEF position and east, north, up axes of a point on WGS 84 (geodetic lon/lat in degrees).
function enu(lonDeg, latDeg, h) {
  const a = 6378137.0, f = 1 / 298.257223563, e2 = f * (2 - f);
  const l = (lonDeg * Math.PI) / 180, p = (latDeg * Math.PI) / 180;
  const N = a / Math.sqrt(1 - e2 * Math.sin(p) ** 2);
  return {
    origin: [(N + h) * Math.cos(p) * Math.cos(l), (N + h) * Math.cos(p) * Math.sin(l), (N * (1 - e2) + h) * Math.sin(p)],
    east: [-Math.sin(l), Math.cos(l), 0],
    north: [-Math.sin(p) * Math.cos(l), -Math.sin(p) * Math.sin(l), Math.cos(p)],
    up: [Math.cos(p) * Math.cos(l), Math.cos(p) * Math.sin(l), Math.sin(p)],
  };
}

// 4x4 column-major helpers.
const identity = () => [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1];
function mul(a, b) {
  const m = new Array(16).fill(0);
  for (let c = 0; c < 4; ++c) for (let r = 0; r < 4; ++r) for (let k = 0; k < 4; ++k) m[4 * c + r] += a[4 * k + r] * b[4 * c + k];
  return m;
}
const apply = (m, p) => [0, 1, 2].map((r) => m[r] * p[0] + m[4 + r] * p[1] + m[8 + r] * p[2] + m[12 + r]);
function trs(t = [0, 0, 0], q = [0, 0, 0, 1], s = [1, 1, 1]) {
  const [x, y, z, w] = q;
  const R = [1 - 2 * (y * y + z * z), 2 * (x * y + z * w), 2 * (x * z - y * w), 0,
             2 * (x * y - z * w), 1 - 2 * (x * x + z * z), 2 * (y * z + x * w), 0,
             2 * (x * z + y * w), 2 * (y * z - x * w), 1 - 2 * (x * x + y * y), 0, 0, 0, 0, 1];
  const S = [s[0], 0, 0, 0, 0, s[1], 0, 0, 0, 0, s[2], 0, 0, 0, 0, 1];
  const T = identity();
  T[12] = t[0]; T[13] = t[1]; T[14] = t[2];
  return mul(T, mul(R, S));
}
const nodeMatrix = (n) => (n.matrix ? Array.from(n.matrix) : trs(n.translation, n.rotation, n.scale));
// 3D Tiles' y-up to z-up for glTF content: (x, y, z) -> (x, -z, y).
const yUpToZUp = [1, 0, 0, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 0, 0, 1];

// An accessor's elements as numbers (normalized integers mapped as glTF says).
function elements(accessor) {
  const v = accessor.value;
  const size = {SCALAR: 1, VEC2: 2, VEC3: 3, VEC4: 4}[accessor.type];
  const scale = !accessor.normalized ? 1 : {5120: 127, 5121: 255, 5122: 32767, 5123: 65535}[accessor.componentType];
  const out = [];
  for (let i = 0; i < accessor.count; ++i) {
    const e = [];
    for (let k = 0; k < size; ++k) e.push(scale === 1 ? v[i * size + k] : Math.max(v[i * size + k] / scale, -1));
    out.push(e);
  }
  return out;
}

// Every node's mesh: its vertices in the tile's frame (z up, every node and instance transform
// applied) per instance, and its triangles counted once per instance.
async function readGlb(file) {
  const content = await parse(bytesOf(file), Tiles3DLoader, {'3d-tiles': {isTileset: false, loadGLTF: true}, gltf: {loadImages: false}});
  if (content.type !== 'glTF') throw new Error(`${file}: read as ${content.type}, not glTF content`);
  const gltf = content.gltf;
  const meshes = [];
  const visit = (node, parent) => {
    const m = mul(parent, nodeMatrix(node));
    for (const child of node.children || []) visit(child, m);
    if (!node.mesh) return;
    let instances = [identity()];
    const inst = node.extensions && node.extensions.EXT_mesh_gpu_instancing;
    if (inst) {
      const acc = (k) => (inst.attributes[k] === undefined ? null : elements(gltf.accessors[inst.attributes[k]]));
      const t = acc('TRANSLATION'), r = acc('ROTATION'), s = acc('SCALE');
      const n = (t || r || s).length;
      instances = [];
      for (let i = 0; i < n; ++i) instances.push(trs(t ? t[i] : undefined, r ? r[i] : undefined, s ? s[i] : undefined));
    }
    const points = [];
    let triangles = 0;
    // The surface's centroid (triangles weighted by area), which the welding of vertices and the
    // quantization grid leave where it is, unlike the mean of the vertices.
    let area = 0;
    const moment = [0, 0, 0];
    for (const prim of node.mesh.primitives) {
      const pos = elements(prim.attributes.POSITION);
      const idx = prim.indices ? prim.indices.count : pos.length;
      triangles += (idx / 3) * instances.length;
      for (const I of instances) {
        const world = mul(yUpToZUp, mul(m, I));
        const placed = pos.map((p) => apply(world, p));
        points.push(...placed);
        const index = prim.indices.value;
        for (let t = 0; t + 2 < idx; t += 3) {
          const [A, B, C] = [placed[index[t]], placed[index[t + 1]], placed[index[t + 2]]];
          const u = [0, 1, 2].map((k) => B[k] - A[k]), v = [0, 1, 2].map((k) => C[k] - A[k]);
          const n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]];
          const s = Math.hypot(...n) / 2;
          area += s;
          for (let k = 0; k < 3; ++k) moment[k] += (s * (A[k] + B[k] + C[k])) / 3;
        }
      }
    }
    meshes.push({name: node.name, points, triangles, instanced: !!inst, centroid: moment.map((x) => x / area)});
  };
  const scene = typeof gltf.scene === 'object' ? gltf.scene : gltf.scenes[gltf.scene || 0];
  for (const node of scene.nodes) visit(node, identity());
  return meshes;
}

function boxOf(volume) {
  if (!volume.box) throw new Error('a bounding volume that is not a box');
  const b = volume.box;
  return {c: b.slice(0, 3), axes: [b.slice(3, 6), b.slice(6, 9), b.slice(9, 12)]};
}
// Whether p lies in the box (its half-axes orthogonal, as a box's are).
function inBox(box, p) {
  const d = [0, 1, 2].map((k) => p[k] - box.c[k]);
  return box.axes.every((u) => {
    const uu = u[0] * u[0] + u[1] * u[1] + u[2] * u[2];
    return Math.abs(d[0] * u[0] + d[1] * u[1] + d[2] * u[2]) <= uu * (1 + 1e-12);
  });
}
function boxCorners(box) {
  const out = [];
  for (let m = 0; m < 8; ++m)
    out.push([0, 1, 2].map((k) => box.c[k] + box.axes.reduce((s, u, j) => s + (m >> j & 1 ? 1 : -1) * u[k], 0)));
  return out;
}

(async () => {
  const tileset = await parse(bytesOf(path.join(dir, 'tileset.json')), Tiles3DLoader,
                              {'3d-tiles': {isTileset: true}});
  if (!tileset.asset || tileset.asset.version !== '1.1') fail(`asset.version ${tileset.asset && tileset.asset.version}, not 1.1`);
  const raw = JSON.parse(fs.readFileSync(path.join(dir, 'tileset.json'), 'utf8'));

  // The root transform against the ellipsoid's formulas. A merged tileset (corbel-cli
  // city-merge) has none: each part's root has its own, a rigid motion (a part whose root is a
  // leaf is placed at the leaf's centre), and the buildings' placement below checks them.
  const want = enu(Number(lonArg), Number(latArg), Number(heightArg));
  let dist = 0;
  const t = raw.root.transform;
  if (t) {
    const origin = [t[12], t[13], t[14]];
    dist = Math.hypot(...origin.map((x, k) => x - want.origin[k]));
    if (!(dist < 1e-3)) fail(`the root transform puts the origin ${dist} m from (${lonArg}, ${latArg}, ${heightArg})`);
    for (const [c, name] of [[0, 'east'], [1, 'north'], [2, 'up']]) {
      const col = t.slice(4 * c, 4 * c + 3);
      const err = Math.max(...col.map((x, k) => Math.abs(x - want[name][k])));
      if (!(err < 1e-9)) fail(`the transform's ${name} axis is off by ${err}`);
    }
  }
  for (const part of t ? [raw.root] : raw.root.children || []) {
    const m = part.transform;
    if (!m) { fail('a part of a merged tileset without a transform'); continue; }
    if (m[3] !== 0 || m[7] !== 0 || m[11] !== 0 || m[15] !== 1) fail('a transform that is not affine');
    for (let a = 0; a < 3; ++a)
      for (let b = 0; b < 3; ++b) {
        const dot = [0, 1, 2].reduce((s, k) => s + m[4 * a + k] * m[4 * b + k], 0);
        // 1e-8: a micrometre over a leaf's 300 m (PROJ's topocentric frames, multiplied, stay
        // within 2e-9 of orthonormal).
        if (!(Math.abs(dot - (a === b ? 1 : 0)) < 1e-8)) fail(`a transform whose axes ${a}, ${b} are not orthonormal (${dot})`);
      }
  }

  let tiles = 0, contents = 0, leafTriangles = 0, blockTiles = 0, glbs = [];
  const walk = async (tile, parent, depth, parentFrame) => {
    ++tiles;
    const box = boxOf(tile.boundingVolume);
    const where = `tile at depth ${depth}${tile.content ? ' (' + tile.content.uri + ')' : ''}`;
    const local = tile.transform ? Array.from(tile.transform) : identity();
    const frame = mul(parentFrame, local);  // the tile's frame in ECEF
    if (parent) {
      if (!(tile.geometricError < parent.geometricError)) fail(`${where}: geometric error ${tile.geometricError} not below its parent's ${parent.geometricError}`);
      const pbox = boxOf(parent.boundingVolume);
      if (!boxCorners(box).every((p) => inBox(pbox, apply(local, p)))) fail(`${where}: its volume is not inside its parent's`);
    }
    const children = tile.children || [];
    if (!children.length && tile.geometricError !== 0) fail(`${where}: a leaf with geometric error ${tile.geometricError}`);
    if (children.length && (tile.refine || (depth === 0 ? null : 'inherited')) === null) fail(`${where}: no refine`);
    if (tile.refine && tile.refine !== 'REPLACE') fail(`${where}: refine ${tile.refine}`);
    let meshes = null;
    if (tile.content) {
      ++contents;
      const file = path.join(dir, tile.content.uri);
      glbs.push(file);
      meshes = await readGlb(file);
      let outside = 0, points = 0;
      for (const m of meshes) for (const p of m.points) { ++points; if (!inBox(box, p)) ++outside; }
      if (outside) fail(`${where}: ${outside} of ${points} vertices outside the bounding volume`);
      if (!children.length) for (const m of meshes) leafTriangles += m.triangles;
      if (!children.length)
        for (const m of meshes) {
          if (m.instanced) continue;
          const c = m.centroid;
          if (placed.has(m.name)) fail(`${m.name}: in two leaf tiles`);
          placed.set(m.name, {ecef: apply(frame, c), d: Math.hypot(c[0], c[1])});
        }
    }
    if (tile.content && children.length) {  // a block tile: one block per building of its child
      ++blockTiles;
      for (const m of meshes) {
        const zs = m.points.map((p) => p[2]);
        const h = Math.max(...zs) - Math.min(...zs);
        if (!(h <= tile.geometricError)) fail(`${where}: block ${m.name} ${h} m high, above the geometric error`);
      }
      const child = await readGlb(path.join(dir, children[0].content.uri));
      const buildings = child.filter((m) => !m.instanced).map((m) => m.name);
      const blocks = meshes.map((m) => m.name);
      if (blocks.length !== new Set(buildings).size || !blocks.every((b) => buildings.includes(b)))
        fail(`${where}: ${blocks.length} blocks for ${new Set(buildings).size} buildings`);
    }
    for (const c of children) await walk(c, tile, depth + 1, frame);
  };
  const placed = new Map();
  await walk(raw.root, null, 0, identity());
  if (!(raw.geometricError >= raw.root.geometricError)) fail('the tileset\'s geometric error is below its root\'s');

  // The same town as one glb.
  const whole = await parse(bytesOf(wholeGlb), GLTFLoader, {gltf: {loadImages: false}});
  const g = postProcessGLTF(whole);
  let wholeTriangles = 0;
  for (const node of g.nodes) {
    if (!node.mesh) continue;
    const inst = node.extensions && node.extensions.EXT_mesh_gpu_instancing;
    const copies = inst ? g.accessors[inst.attributes.TRANSLATION].count : 1;
    for (const p of node.mesh.primitives) wholeTriangles += (p.indices.count / 3) * copies;
  }
  if (leafTriangles !== wholeTriangles) fail(`the leaves hold ${leafTriangles} triangles, the whole town ${wholeTriangles}`);

  // Where the footprint file puts each building.
  const R = Number(radiusArg), lon0 = Number(lonArg), lat0 = Number(latArg), h0 = Number(heightArg);
  const rad = Math.PI / 180, a = 6378137.0, f = 1 / 298.257223563, e2 = f * (2 - f);
  const w = 1 - e2 * Math.sin(lat0 * rad) ** 2;
  const k = Math.abs(a / Math.sqrt(w) / R - 1) + Math.abs((a * (1 - e2)) / w ** 1.5 / R - 1) + 1e-3;
  let worst = 0, compared = 0;
  for (const m of await readGlb(wholeGlb)) {
    if (m.instanced) continue;
    if (!placed.has(m.name)) { fail(`${m.name}: in the whole town, in no leaf tile`); continue; }
    const [x, y, z] = m.centroid;
    const lat = lat0 + y / R / rad, lon = lon0 + x / (R * Math.cos(lat0 * rad)) / rad;
    const truth = enu(lon, lat, h0 + z).origin;
    const p = placed.get(m.name);
    const err = Math.hypot(...truth.map((t, i) => t - p.ecef[i]));
    const bound = k * p.d + (p.d * p.d) / (2 * R) + 0.002;
    worst = Math.max(worst, err);
    ++compared;
    if (!(err <= bound)) fail(`${m.name}: placed ${err.toFixed(3)} m from where the footprints put it (allowed ${bound.toFixed(3)} m, ${p.d.toFixed(0)} m from its tile's origin)`);
  }
  if (compared !== placed.size) fail(`${compared} of the tiles' ${placed.size} buildings found in the whole town`);

  fs.writeFileSync(path.join(dir, '..', path.basename(dir) + '.glbs'), glbs.join('\n') + '\n');
  console.log(JSON.stringify({tiles, contents, blockTiles, leafTriangles, wholeTriangles, originError_m: dist,
                              buildingsPlaced: compared, worstPlacement_m: worst}));
  for (const f of failures) console.log('FAIL ' + f);
  process.exit(failures.length ? 1 : 0);
})().catch((e) => {
  console.error(e);
  process.exit(2);
});
