// The lab explorer's page (common/app/explore_server.cpp serves it; no build step, no
// network: three.js comes from Debian's libjs-three through the same server).
// The server renders; this page shows its frames, moves its camera, and draws picked rays.
'use strict';

const $ = (id) => document.getElementById(id);
const params = new URLSearchParams(location.search);
const format = params.get('format') || 'rgb';  // how frames travel: rgb (chosen, see the book), rgba, png, jpeg
// The session's token, from the address the explorer printed: sent with every request as a
// header, never in a URL (book §0.11 says why). Without it the server refuses, and says so.
const token = params.get('token') ?? '';
const api = (url, options = {}) => fetch(url, {...options, headers: {...options.headers, 'X-Rtlab-Token': token}});

// What the tests and ./lab bench explore read (tests/explore_browser_test.py, bench/explore_bench.py).
const rtlab = window.rtlab = {
  api, format, framesDrawn: 0, frame: null, generation: 0, moveLatencies: [], clickLatencies: [],
  pick: null, pickDrawnAt: 0, state: null, errors: [],
};

let state = null;       // /api/state
let cam = null;         // the camera, as the scene file writes it
let home = null;        // the scene's own camera: "reset view"
let sceneObject = null; // the scene file, parsed (null for a scene made in code)
let tree = null;        // the picked pixel's ray tree, flattened

// ---- small vector helpers ----
const add = (a, b) => [a[0] + b[0], a[1] + b[1], a[2] + b[2]];
const sub = (a, b) => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const mul = (a, s) => [a[0] * s, a[1] * s, a[2] * s];
const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
const len = (a) => Math.sqrt(dot(a, a));
const unit = (a) => mul(a, 1 / len(a));
// Rotates v about the unit axis k by angle a (Rodrigues).
const rotate = (v, k, a) => add(add(mul(v, Math.cos(a)), mul(cross(k, v), Math.sin(a))),
  mul(k, dot(k, v) * (1 - Math.cos(a))));

async function getJson(url, options) {
  const r = await api(url, options);
  const j = await r.json();
  if (!r.ok) throw new Error(j.error || `HTTP ${r.status}`);
  return j;
}
// A scene file as the lab writes them: one key a line, arrays of numbers on one line.
const pretty = (value) => JSON.stringify(value, null, 1)
  .replace(/\[\s+([^\[\]{}]*?)\s+\]/g, (_, inner) => `[${inner.split(/,\s+/).join(', ')}]`);
const post = (url, body) => getJson(url, {method: 'POST', body: typeof body === 'string' ? body : JSON.stringify(body)});

// ---- the frames: long polling, drawn as they come ----
const frameCanvas = $('frame');
const frameContext = frameCanvas.getContext('2d');
const scratch = document.createElement('canvas');  // a smaller preview frame, before scaling up
const shown = [];  // times frames were drawn, for frames per second

function setViewSize(w, h) {
  if (frameCanvas.width === w && frameCanvas.height === h) return;
  frameCanvas.width = w; frameCanvas.height = h;
  rays.setSize(w, h);
  drawRays();
}

// rgb frames (3 bytes a pixel, a quarter fewer to send) made RGBA in a reused ImageData:
// one 32-bit store a pixel (every browser here is little-endian: R is the lowest byte).
let unpacked = null;
function imageOf(buffer, w, h) {
  if (format === 'rgba') return new ImageData(new Uint8ClampedArray(buffer), w, h);
  if (!unpacked || unpacked.width !== w || unpacked.height !== h) unpacked = new ImageData(w, h);
  const src = new Uint8Array(buffer), dst = new Uint32Array(unpacked.data.buffer);
  for (let i = 0, j = 0; i < dst.length; ++i, j += 3)
    dst[i] = 0xff000000 | (src[j + 2] << 16) | (src[j + 1] << 8) | src[j];
  return unpacked;
}

async function drawFrame(buffer, w, h) {
  if (format === 'rgba' || format === 'rgb') {
    const image = imageOf(buffer, w, h);
    if (w === frameCanvas.width && h === frameCanvas.height) return frameContext.putImageData(image, 0, 0);
    scratch.width = w; scratch.height = h;
    scratch.getContext('2d').putImageData(image, 0, 0);
    frameContext.drawImage(scratch, 0, 0, frameCanvas.width, frameCanvas.height);
  } else {
    const bitmap = await createImageBitmap(new Blob([buffer]));
    frameContext.drawImage(bitmap, 0, 0, frameCanvas.width, frameCanvas.height);
  }
}

// One request always waits at the server: the next frame's is sent as soon as this one's
// headers come, so the server can answer it while this frame's bytes arrive and are drawn
// (fetch, read, draw, fetch again would leave the server's new frame waiting for the page).
function ask(after) {
  const asked = performance.now();
  return api(`/api/frame?after=${after}&format=${format}&wait=1000`)
    .then((r) => ({r, asked}), (error) => ({error, asked}));
}

async function frameLoop() {
  let after = 0;
  let next = ask(after);
  for (;;) {
    try {
      const {r, asked, error} = await next;
      if (error) throw error;
      const renderError = r.headers.get('X-Render-Error');
      $('render-error').textContent = renderError ? `render: ${renderError}` : '';
      if (r.status === 204) { next = ask(after); continue; }
      if (!r.ok) throw new Error((await r.json()).error);
      const h = (k) => Number(r.headers.get(k));
      const headersAt = performance.now();
      const id = h('X-Frame-Id');
      if (id <= after) { r.body?.cancel(); next = ask(after); continue; }
      after = id;
      next = ask(after);
      const buffer = await r.arrayBuffer();
      const received = performance.now();
      const f = {
        id, generation: h('X-Generation'), width: h('X-Width'), height: h('X-Height'),
        samples: h('X-Samples'), target: h('X-Target-Samples'), renderMs: h('X-Render-Ms'),
        passMs: h('X-Pass-Ms'), finishMs: h('X-Finish-Ms'),
        encodeMs: h('X-Encode-Ms'), mrays: h('X-Mrays'), bytes: buffer.byteLength,
        nodes: h('X-Nodes-Per-Ray'), primitives: h('X-Primitives-Per-Ray'),
        transferMs: received - headersAt, waitedMs: headersAt - asked,
      };
      const drawStart = performance.now();
      await drawFrame(buffer, f.width, f.height);
      const drawn = performance.now();
      f.drawMs = drawn - drawStart;
      f.drawnAt = drawn;
      rtlab.frame = f;
      rtlab.framesDrawn++;
      if (f.generation > rtlab.generation) {
        if (moveStarted !== null) {  // the first frame made after the camera moved
          rtlab.moveLatencies.push(drawn - moveStarted);
          moveStarted = null;
        }
        rtlab.generation = f.generation;
      }
      shown.push(drawn);
      while (shown.length && shown[0] < drawn - 1000) shown.shift();
      $('fps').textContent = `${shown.length} fps`;
      $('mrays').textContent = `${f.mrays.toFixed(1)} Mrays/s · ${f.nodes.toFixed(1)} boxes, ` +
        `${f.primitives.toFixed(1)} primitives per ray`;
      $('samples').textContent = f.width < frameCanvas.width
        ? `preview ${f.width}×${f.height}` : `${f.samples}/${f.target} spp`;
      $('timing').textContent = `render ${f.renderMs.toFixed(1)} (pass ${f.passMs.toFixed(1)}) · ` +
        `finish ${f.finishMs.toFixed(1)} · encode ${f.encodeMs.toFixed(1)} · ` +
        `transfer ${f.transferMs.toFixed(1)} · draw ${f.drawMs.toFixed(1)} ms`;
    } catch (e) {
      $('render-error').textContent = `frames: ${e.message}`;
      await new Promise((done) => setTimeout(done, 500));
      next = ask(after);
    }
  }
}

// ---- the camera: orbit, pan, zoom, field of view ----
let moveStarted = null;  // when the first camera change not yet seen in a frame was made
let cameraSending = false, cameraAgain = false;

async function sendCamera() {
  if (cameraSending) { cameraAgain = true; return; }
  cameraSending = true;
  try {
    do {
      cameraAgain = false;
      await post('/api/camera', cam);
      $('error').textContent = '';
    } while (cameraAgain);
  } catch (e) {
    $('error').textContent = e.message;
  } finally {
    cameraSending = false;
  }
}

function cameraChanged() {
  if (moveStarted === null) moveStarted = performance.now();
  showCameraControls();
  drawRays();
  sendCamera();
}

function frameOf() {  // the camera's frame: forward, right, up
  const f = unit(sub(cam.target, cam.eye));
  const r = unit(cross(f, cam.up));
  return {f, r, u: cross(r, f)};
}

function orbit(dx, dy) {
  const up = unit(cam.up);
  let offset = sub(cam.eye, cam.target);
  offset = rotate(offset, up, -dx * 0.008);
  const {r} = frameOf();
  const turned = rotate(offset, r, -dy * 0.008);
  // Not over the pole: the view would flip about the up vector.
  const c = dot(unit(turned), up);
  if (Math.abs(c) < 0.995) offset = turned;
  cam.eye = add(cam.target, offset);
  cameraChanged();
}

function pan(dx, dy) {
  const {r, u} = frameOf();
  const extent = cam.projection === 'orthographic' ? cam.window_height
    : 2 * len(sub(cam.target, cam.eye)) * Math.tan((cam.fov ?? 45) * Math.PI / 360);
  const perPixel = extent / frameCanvas.height;
  const move = add(mul(r, -dx * perPixel), mul(u, dy * perPixel));
  cam.eye = add(cam.eye, move);
  cam.target = add(cam.target, move);
  cameraChanged();
}

function zoom(steps) {
  const factor = Math.pow(1.1, steps);
  if (cam.projection === 'orthographic') cam.window_height *= factor;
  else cam.eye = add(cam.target, mul(sub(cam.eye, cam.target), factor));
  cameraChanged();
}

function changeFov(steps) {
  if (cam.projection === 'orthographic') return zoom(steps);
  cam.fov = Math.min(179, Math.max(1, (cam.fov ?? 45) * Math.pow(1.08, steps)));
  cameraChanged();
}

const view = $('view');
let drag = null;
view.addEventListener('contextmenu', (e) => e.preventDefault());
view.addEventListener('mousedown', (e) => {
  view.focus();
  drag = {x: e.clientX, y: e.clientY, startX: e.clientX, startY: e.clientY, pan: e.button === 2 || e.shiftKey, moved: false};
});
window.addEventListener('mousemove', (e) => {
  if (!drag) return hover(e);
  const dx = e.clientX - drag.x, dy = e.clientY - drag.y;
  if (!drag.moved && Math.hypot(e.clientX - drag.startX, e.clientY - drag.startY) < 3) return;
  drag.moved = true;
  drag.x = e.clientX; drag.y = e.clientY;
  if (drag.pan) pan(dx, dy); else orbit(dx, dy);
});
window.addEventListener('mouseup', (e) => {
  if (drag && !drag.moved && e.button === 0) {
    const box = frameCanvas.getBoundingClientRect();
    const x = Math.floor((e.clientX - box.left) * frameCanvas.width / box.width);
    const y = Math.floor((e.clientY - box.top) * frameCanvas.height / box.height);
    if (x >= 0 && y >= 0 && x < frameCanvas.width && y < frameCanvas.height) pickPixel(x, y);
  }
  drag = null;
});
view.addEventListener('wheel', (e) => {
  e.preventDefault();
  const steps = Math.sign(e.deltaY);
  if (e.altKey) changeFov(steps); else zoom(steps);
}, {passive: false});
view.addEventListener('keydown', (e) => {
  const keys = {
    ArrowLeft: () => orbit(-20, 0), ArrowRight: () => orbit(20, 0), ArrowUp: () => orbit(0, -20),
    ArrowDown: () => orbit(0, 20), '+': () => zoom(-1), '=': () => zoom(-1), '-': () => zoom(1),
    '[': () => changeFov(-1), ']': () => changeFov(1), r: () => resetView(),
    w: () => pan(0, 20), s: () => pan(0, -20), a: () => pan(20, 0), d: () => pan(-20, 0),
  };
  if (keys[e.key]) { e.preventDefault(); keys[e.key](); }
});

function resetView() {
  cam = structuredClone(home);
  cameraChanged();
}

// ---- the camera's lens and shutter fields ----
function showCameraControls() {
  $('fov').value = cam.fov ?? '';
  $('aperture').value = cam.aperture ?? 0;
  $('focus').value = cam.focus_distance ?? '';
  $('lens').value = cam.lens ?? 'square';
  $('shutter-open').value = cam.shutter ? cam.shutter[0] : 0;
  $('shutter-close').value = cam.shutter ? cam.shutter[1] : 1;
}

function readCameraControls() {
  const number = (id) => $(id).value === '' ? undefined : Number($(id).value);
  if (cam.projection !== 'orthographic') cam.fov = number('fov') ?? cam.fov;
  const aperture = number('aperture') ?? 0;
  delete cam.aperture; delete cam.focus_distance; delete cam.lens;
  if (aperture > 0) {
    cam.aperture = aperture;
    if (number('focus') !== undefined) cam.focus_distance = number('focus');
    cam.lens = $('lens').value;
  }
  const open = number('shutter-open') ?? 0, close = number('shutter-close') ?? 1;
  if (open !== 0 || close !== 1) cam.shutter = [open, close]; else delete cam.shutter;
  cameraChanged();
}
for (const id of ['fov', 'aperture', 'focus', 'lens', 'shutter-open', 'shutter-close'])
  $(id).addEventListener('change', readCameraControls);

// ---- command-line options: every control is one option, read by the chapter's parser ----
// The controls are read when one changes, and the sends go to the server one after another:
// two quick changes sent at once could come back in either order, and the first's success
// would then wipe the second's refusal from the page (and its state reload would overwrite
// a value the user had just typed).
let optionsSent = Promise.resolve();
function sendOptions() {
  const args = [];
  for (const el of document.querySelectorAll('[data-option]'))
    if (el.value !== '') args.push(el.dataset.option, el.value);
  optionsSent = optionsSent.then(() => postOptions(args));
  return optionsSent;
}
async function postOptions(args) {
  try {
    await post('/api/options', args);
    $('error').textContent = '';
    await loadState(false);
  } catch (e) {
    $('error').textContent = e.message;
  }
}
for (const el of document.querySelectorAll('[data-option]')) el.addEventListener('change', sendOptions);

// ---- the scene file: edited as text, or through the shading and offset controls ----
async function sendScene(text) {
  try {
    await post('/api/scene', text);
    $('scene-error').textContent = '';
    return true;
  } catch (e) {
    $('scene-error').textContent = e.message;  // FILE:LINE:COL: /pointer: message, as the loader says
    return false;
  }
}

$('apply').addEventListener('click', async () => {
  if (await sendScene($('text').value)) await loadState(true);
});

async function sceneControlChanged() {
  if (!sceneObject) return;
  const scene = structuredClone(sceneObject);
  scene.camera = cam;  // keep the view where it is
  scene.shading = $('shading').value;
  const offset = {method: $('offset').value};
  if ($('epsilon').value !== '') offset.epsilon = Number($('epsilon').value);
  scene.offset = offset;
  const text = pretty(scene);
  if (await sendScene(text)) {
    sceneObject = scene;
    $('text').value = text;
    await loadState(false);
  }
}
for (const id of ['shading', 'offset', 'epsilon']) $(id).addEventListener('change', sceneControlChanged);

$('copy').addEventListener('click', async () => {
  const text = pretty(sceneObject ? {...sceneObject, camera: cam} : {camera: cam});
  try {
    await navigator.clipboard.writeText(text);
    $('error').textContent = 'copied';
  } catch (e) {  // no clipboard (a page not in focus): show it instead
    $('text').value = text;
    $('error').textContent = 'copied into the scene file box (the clipboard was refused)';
  }
});
$('reset').addEventListener('click', resetView);
$('clear').addEventListener('click', () => { tree = null; drawRays(); });

// ---- state: the chapter, scene, options and choices ----
function fillSelect(id, names, value, empty) {
  const el = $(id);
  el.replaceChildren();
  if (empty) el.append(new Option(empty, ''));
  for (const n of names) el.append(new Option(n, n));
  el.value = value ?? '';
}

async function loadState(resetCamera) {
  state = rtlab.state = await getJson('/api/state');
  const b = state.build;
  $('chapter').textContent = `${state.chapter}: ${state.title} · scene ${state.scene}`;
  $('build').textContent = b.track === 'solutions'
    ? `reference exercises (solutions track), Real=${b.real}`
    : `your exercises (exercises track; from solutions/: ${b.from_solutions}), Real=${b.real}` +
      (b.your_exercises ? ` · ran yours: ${b.your_exercises}` : '');
  const o = state.options;
  fillSelect('accel', state.choices.accel, o.accel);
  fillSelect('pattern', state.choices.pattern, o.pattern);
  fillSelect('filter', state.choices.filter, o.filter);
  fillSelect('lens', state.choices.lens, 'square');
  for (const k of ['depth', 'spp', 'seed', 'threads', 'width', 'height']) $(k).value = o[k];
  if (resetCamera || !cam) {
    cam = structuredClone(state.camera);
    home = structuredClone(state.camera);
    sceneObject = state.text ? JSON.parse(state.text) : null;
    $('text').value = state.text ?? '// this scene is made in code (chapters 01-04): only the camera and options change';
    showCameraControls();
  }
  $('scene-controls').disabled = !sceneObject;
  fillSelect('shading', state.choices.shading, sceneObject?.shading ?? 'phong');
  fillSelect('offset', state.choices.offset, sceneObject?.offset?.method ?? 'robust');
  $('epsilon').value = sceneObject?.offset?.epsilon ?? '';
  setViewSize(o.width, o.height);
}

// ---- click a pixel: --pick's numbers and the ray tree ----
const kindColours = {camera: 0xffffff, shadow: 0xffd54f, reflection: 0x4fc3f7, refraction: 0xba68c8};
const fmt = (v) => Array.isArray(v) ? `(${v.map(fmt).join(', ')})` : typeof v === 'number' ? String(v) : String(v);

async function pickPixel(x, y) {
  const clicked = performance.now();
  try {
    const p = await getJson(`/api/pick?x=${x}&y=${y}`);
    showPick(p);
    drawRays();
    rtlab.pick = p;
    rtlab.pickDrawnAt = performance.now();
    rtlab.clickLatencies.push(rtlab.pickDrawnAt - clicked);
  } catch (e) {
    $('error').textContent = e.message;
  }
}

function showPick(p) {
  const rows = [['pixel', p.pixel], ['hit', p.hit]];
  if (p.hit) {
    rows.push(['surface', p.surface], ['t', p.t], ['point', p.point], ['normal', p.normal]);
    if (p.shading_normal) rows.push(['shading normal', p.shading_normal]);
    if (p.triangle !== undefined) rows.push(['triangle', p.triangle]);
    if (p.beta !== undefined) rows.push(['β', p.beta], ['γ', p.gamma]);
    if (p.operand) rows.push(['operand', p.operand]);
  }
  rows.push(['colour', p.color]);
  const table = $('pick-table');
  table.replaceChildren();
  for (const [k, v] of rows) {
    const tr = table.insertRow();
    tr.insertCell().textContent = k;
    const td = tr.insertCell();
    td.textContent = fmt(v);
    td.id = `pick-${k === 'β' ? 'beta' : k === 'γ' ? 'gamma' : k.replace(' ', '-')}`;
  }
  tree = [];
  const walk = (n, depth) => {
    tree.push({...n, level: depth});
    for (const c of n.children ?? []) walk(c, depth + 1);
  };
  if (p.tree) walk(p.tree, 0);
  const list = $('tree');
  list.replaceChildren();
  tree.forEach((n, i) => {
    const li = document.createElement('li');
    li.textContent = `${'  '.repeat(n.level)}${n.kind}${n.hit ? ` → ${n.hit.surface} t=${n.hit.t}` : ''}` +
      `${n.kind === 'shadow' ? (n.blocked ? ' blocked' : ' reaches the light') : ''}${n.note ? ` (${n.note})` : ''}`;
    li.title = describe(n);
    li.addEventListener('mouseenter', () => { hot = i; li.classList.add('hot'); drawRays(); });
    li.addEventListener('mouseleave', () => { hot = -1; li.classList.remove('hot'); drawRays(); });
    list.append(li);
  });
  // The side view (--svg) as an image: drawn once, not again with every frame; fetched after
  // the numbers and the 3D rays, which do not wait for it. Fetched with the token and shown
  // from memory (a blob: address); as an image, nothing in it could run.
  const box = $('svg');
  box.replaceChildren();
  if (p.tree) showSvg(box, `/api/tree.svg?x=${p.pixel[0]}&y=${p.pixel[1]}`);
  else box.append(Object.assign(document.createElement('p'), {className: 'hint',
    textContent: 'This scene\'s shading records no ray tree (use whitted).'}));
}

let svgUrl = null, svgAsked = 0;
async function showSvg(box, url) {
  const asked = ++svgAsked;
  try {
    const r = await api(url);
    if (!r.ok) throw new Error((await r.json()).error);
    const blob = await r.blob();
    if (asked !== svgAsked) return;  // another pixel was clicked meanwhile
    if (svgUrl) URL.revokeObjectURL(svgUrl);
    svgUrl = URL.createObjectURL(blob);
    box.replaceChildren(Object.assign(document.createElement('img'), {alt: 'the ray tree seen from the side', src: svgUrl}));
  } catch (e) {
    $('error').textContent = `side view: ${e.message}`;
  }
}

function describe(n) {
  let s = `${n.kind} ray, depth ${n.depth}\norigin ${fmt(n.origin)}\ndirection ${fmt(n.direction)}`;
  if (n.weight) s += `\nweight ${fmt(n.weight.value)} (${n.weight.of})`;
  s += `\nradiance ${fmt(n.radiance)}`;
  if (n.contributes) s += `\ncontributes ${fmt(n.contributes)}`;
  return s;
}

// ---- the ray tree in 3D, over the view (three.js from libjs-three) ----
const raysCanvas = $('rays');
const rays = new THREE.WebGLRenderer({canvas: raysCanvas, alpha: true, antialias: true});
rays.setPixelRatio(1);
const overlay = new THREE.Scene();
let hot = -1;
let segments = [];  // [start, end] of each node of `tree`, in world space

function threeCamera() {
  const w = frameCanvas.width, h = frameCanvas.height;
  let c;
  if (cam.projection === 'orthographic') {
    const half = cam.window_height / 2;
    c = new THREE.OrthographicCamera(-half * w / h, half * w / h, half, -half, 1e-4, 1e6);
  } else {
    c = new THREE.PerspectiveCamera(cam.fov ?? 45, w / h, 1e-3, 1e6);
  }
  c.position.set(...cam.eye);
  c.up.set(...cam.up);
  c.lookAt(...cam.target);
  c.updateMatrixWorld();
  return c;
}

let raysBlank = false;  // the 3D canvas shows no rays: a camera move need not draw it again
function drawRays() {
  if (!cam || (!tree && raysBlank)) return;
  while (overlay.children.length) overlay.remove(overlay.children[0]);
  segments = [];
  if (tree) {
    const reach = 2 * len(sub(cam.target, cam.eye)) + 1;  // how far a ray that hits nothing is drawn
    tree.forEach((n, i) => {
      const end = n.hit ? n.hit.point
        : n.kind === 'shadow' && n.interval[1] !== null ? add(n.origin, mul(n.direction, n.interval[1]))
        : add(n.origin, mul(unit(n.direction), reach));
      segments.push([n.origin, end]);
      let colour = kindColours[n.kind] ?? 0x81c784;
      if (n.kind === 'shadow' && n.blocked) colour = 0xe57373;
      const geometry = new THREE.BufferGeometry().setFromPoints([new THREE.Vector3(...n.origin), new THREE.Vector3(...end)]);
      const material = new THREE.LineBasicMaterial({color: i === hot ? 0xff5722 : colour, depthTest: false});
      overlay.add(new THREE.Line(geometry, material));
      if (n.hit) {
        const dot3 = new THREE.Mesh(new THREE.SphereGeometry(reach / 400, 8, 6),
          new THREE.MeshBasicMaterial({color: colour, depthTest: false}));
        dot3.position.set(...n.hit.point);
        overlay.add(dot3);
      }
    });
  }
  rtlab.raysDrawn = segments.length;
  rays.render(overlay, threeCamera());
  raysBlank = !tree;
}

// Hovering a drawn ray: its kind, weight and radiance.
function hover(e) {
  const tip = $('tip');
  if (!segments.length) { tip.style.display = 'none'; return; }
  const box = frameCanvas.getBoundingClientRect();
  const mx = e.clientX - box.left, my = e.clientY - box.top;
  if (mx < 0 || my < 0 || mx > box.width || my > box.height) { tip.style.display = 'none'; return; }
  const c = threeCamera();
  const screen = (p) => {
    const v = new THREE.Vector3(...p).project(c);
    return [(v.x + 1) / 2 * box.width, (1 - v.y) / 2 * box.height, v.z];
  };
  let best = -1, bestDistance = 6;
  segments.forEach(([a, b], i) => {
    const [ax, ay, az] = screen(a), [bx, by, bz] = screen(b);
    if (az > 1 || bz > 1) return;
    const dx = bx - ax, dy = by - ay, l2 = dx * dx + dy * dy;
    const t = l2 > 0 ? Math.max(0, Math.min(1, ((mx - ax) * dx + (my - ay) * dy) / l2)) : 0;
    const d = Math.hypot(mx - (ax + t * dx), my - (ay + t * dy));
    if (d < bestDistance) { bestDistance = d; best = i; }
  });
  if (best !== hot) { hot = best; drawRays(); }
  if (best < 0) { tip.style.display = 'none'; return; }
  tip.textContent = describe(tree[best]);
  tip.style.left = `${mx + 12}px`;
  tip.style.top = `${my + 12}px`;
  tip.style.display = 'block';
}

// Compiles the line and dot shaders once at the start, so that the first click does not pay
// for it (software WebGL takes a few hundred milliseconds).
function warmUp() {
  const line = new THREE.Line(new THREE.BufferGeometry().setFromPoints([new THREE.Vector3(0, 0, 0), new THREE.Vector3(1, 1, 1)]),
    new THREE.LineBasicMaterial({depthTest: false}));
  const dot3 = new THREE.Mesh(new THREE.SphereGeometry(0.01, 8, 6), new THREE.MeshBasicMaterial({depthTest: false}));
  overlay.add(line, dot3);
  rays.render(overlay, threeCamera());
  raysBlank = false;
}

(async () => {
  try {
    await loadState(true);
    warmUp();
    drawRays();
    frameLoop();
  } catch (e) {
    $('error').textContent = `cannot start: ${e.message}`;
  }
})();
