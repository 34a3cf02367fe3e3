// node three_check.mjs F2 SCENE FILE.glb SECONDS...: three.js loads FILE.glb
// (GLTFLoader, as a web page does), an AnimationMixer plays its animation to
// each time (`last`: the scene's last frame), and the world transform of
// every shape's node (extras.f2Shape, in node order, those hidden at scale 0
// left out) and the camera's must match what `F2 export SCENE --prims`
// writes for that time (frame = seconds x the fps in the file's scene
// extras), mirrored into glTF's frame (z -> -z): positions within 1e-3 of
// the scene's size (the diagonal of its primitives' bounds), rotations
// within half a degree.
import { execFileSync } from 'child_process';
import fs from 'fs';
import { AnimationMixer, LoopOnce, Matrix4, Quaternion, Texture, Vector3 } from 'three';
import { GLTFLoader } from 'three/examples/jsm/loaders/GLTFLoader.js';

const [f2, scene, file, ...times] = process.argv.slice(2);
const data = fs.readFileSync(file);
// Node has no image decoder (a browser's GLTFLoader makes the checker PNG a
// texture): an empty texture stands in, the transforms are what is checked.
const loader = new GLTFLoader().register(() => ({ name: 'f2_no_images', loadTexture: async () => new Texture() }));
const gltf = await new Promise((resolve, reject) =>
  loader.parse(data.buffer.slice(data.byteOffset, data.byteOffset + data.length), '', resolve, reject));
const { fps, lastFrame } = gltf.parser.json.scenes[0].extras.f2;

let mixer = null, action = null;
if (gltf.animations.length > 0) {
  mixer = new AnimationMixer(gltf.scene);
  // Played once and held at its end, as F2 holds the last keys (a mixer loops by default).
  action = mixer.clipAction(gltf.animations[0]);
  action.setLoop(LoopOnce);
  action.clampWhenFinished = true;
}

// Objects by glTF node index: the loader records where each came from.
const byNode = new Map();
gltf.scene.traverse((o) => {
  const a = gltf.parser.associations.get(o);
  if (a && a.nodes !== undefined) byNode.set(a.nodes, o);
});
const shapes = [];
let camera = null;
gltf.parser.json.nodes.forEach((n, i) => {
  if (n.extras && n.extras.f2Shape !== undefined) shapes.push([n.extras.f2Shape, byNode.get(i)]);
  if (n.camera !== undefined) camera = byNode.get(i);
});

// A 3x4 matrix of the prims, mirrored: S·M·S with S = diag(1, 1, -1).
const mirrored = (m) => new Matrix4().set(
  m[0], m[1], -m[2], m[3], m[4], m[5], -m[6], m[7], -m[8], -m[9], m[10], -m[11], 0, 0, 0, 1);
const maxTurn = 1 - Math.cos((0.5 * Math.PI / 180) / 2);  // 1 - |q1.q2| of half a degree

let failures = 0;
function check(seconds) {
  const frame = seconds * fps;
  const text = execFileSync(f2, ['export', scene, '--prims', '--frame', String(frame)],
                              { encoding: 'utf8', stdio: ['ignore', 'pipe', 'pipe'] });
  const lines = text.split('\n').map((l) => l.trim().split(/\s+/));
  const records = lines.filter((f) => ['sphere', 'cylinder', 'box'].includes(f[0])).map((f) => f.map(Number));
  const lo = [Infinity, Infinity, Infinity], hi = [-Infinity, -Infinity, -Infinity];
  for (const f of records) {
    const reach = Math.hypot(f[1], f[2] / 2) + Math.hypot(f[3], f[4], f[5]) / 2;  // unused sizes are 0
    [f[9], f[13], f[17]].forEach((c, a) => { lo[a] = Math.min(lo[a], c - reach); hi[a] = Math.max(hi[a], c + reach); });
  }
  const size = records.length ? Math.hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]) : 1;

  if (mixer) {
    action.reset().play();  // a finished action is paused: start again from 0
    mixer.setTime(seconds);
  }
  gltf.scene.updateMatrixWorld(true);
  const visible = shapes.filter(([, o]) => Math.abs(o.matrixWorld.determinant()) > 0.5);
  const worst = { position: 0, rotation: 0 };
  const compare = (name, object, m) => {
    const want = mirrored(m), got = object.matrixWorld;
    const p = new Vector3().setFromMatrixPosition(got).distanceTo(new Vector3().setFromMatrixPosition(want));
    const q1 = new Quaternion().setFromRotationMatrix(got), q2 = new Quaternion().setFromRotationMatrix(want);
    const r = 1 - Math.abs(q1.dot(q2));
    worst.position = Math.max(worst.position, p);
    worst.rotation = Math.max(worst.rotation, r);
    if ((p > size * 1e-3 || r > maxTurn) && failures++ < 10)
      console.log(`FAIL ${file} at ${seconds} s, ${name}: ${p} apart, 1 - |q1.q2| = ${r}`);
  };
  if (visible.length !== records.length) {
    console.log(`FAIL ${file} at ${seconds} s: ${visible.length} visible shape nodes, ${records.length} primitives`);
    failures++;
    return;
  }
  visible.forEach(([name, o], k) => compare(name, o, records[k].slice(6, 18)));
  // A glTF camera looks down its -Z; F2's forward +z mirrored is -Z: no extra turn.
  compare('camera', camera, lines.find((f) => f[0] === 'camera').slice(4, 16).map(Number));
  console.log(`${file} at ${seconds} s (frame ${frame}): ${visible.length} shapes and the camera, worst ` +
              `${worst.position.toPrecision(3)} apart (size ${size.toPrecision(4)}), 1 - |q1.q2| ${worst.rotation.toPrecision(3)}`);
}

// Past the last frame the animation holds its end, as F2 holds its last keys;
// a drive (SPEC 10.7) would go on in F2: such times are checked at the end.
for (const t of times) check(t === 'last' ? lastFrame / fps : Math.min(Number(t), lastFrame / fps));
process.exit(failures ? 1 : 0);
