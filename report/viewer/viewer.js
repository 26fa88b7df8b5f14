// foresight's 3D viewer (docs/VIEWER.md): replays the scene traces embedded in the page as JSON
// (<script id="scene-data">, format in report/scene_trace_json.h) with three.js. The frame F is
// the field's: x towards the opponent goal, y left, z up, metres.
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';

const data = JSON.parse(document.getElementById('scene-data').textContent);
const $ = id => document.getElementById(id);
const FLASH_S = 0.25;  // a contact stays visible this long (simulated time) after it happened
const TEAM_COLOURS = [0x0072b2, 0xd55e00];
const TRIAL_COLOURS = [0xe69f00, 0x56b4e9, 0x009e73, 0xf0e442, 0x0072b2, 0xd55e00, 0xcc79a7,
                       0x999999];

// ---- decoding: integers in fixed units back to metres, seconds, quaternions ----
function decodeTrace(tr) {
  const u = tr.units;
  const frames = tr.t.map((t, i) => {
    const b = tr.ball[i];
    return {
      t: t / u.s,
      phase: tr.phase[i],
      ball: new THREE.Vector3(b[0] / u.m, b[1] / u.m, b[2] / u.m),
      ballQ: new THREE.Quaternion(b[3], b[4], b[5], b[6]).normalize(),
      spin: new THREE.Vector3(b[7] / u.rad_per_s, b[8] / u.rad_per_s, b[9] / u.rad_per_s),
      links: decodePoses(tr.links_pose[i], u),
      bodies: (tr.bodies_pose[i] || []).length
          ? Array.from({length: tr.bodies_pose[i].length / 3}, (_, k) => ({
              x: tr.bodies_pose[i][3 * k] / u.m, y: tr.bodies_pose[i][3 * k + 1] / u.m,
              h: tr.bodies_pose[i][3 * k + 2] / u.heading_rad}))
          : null,
    };
  });
  // The robot holds its last simulated pose once the roll phase has it no more.
  let last = null;
  for (const f of frames) { if (f.links) last = f.links; else f.links = last; }
  const contacts = tr.contacts.map(c => ({
    t: c[0] / u.s, a: c[1], b: c[2], p: new THREE.Vector3(c[3] / u.m, c[4] / u.m, c[5] / u.m),
    impulse: c[6] / u.N_s}));
  const obstacles = tr.obstacles.map(o => decodePoses(o, u));
  return {frames, contacts, obstacles, links: tr.links, phases: tr.phases, bodies: tr.bodies};
}

function decodePoses(a, u) {
  if (!a || a.length === 0) return null;
  const poses = [];
  for (let k = 0; k < a.length; k += 7) {
    poses.push({p: new THREE.Vector3(a[k] / u.m, a[k + 1] / u.m, a[k + 2] / u.m),
                q: new THREE.Quaternion(a[k + 3], a[k + 4], a[k + 5], a[k + 6]).normalize()});
  }
  return poses;
}

// Index i of the frame with t_i <= t < t_{i+1} (clamped) and the share of the way to i + 1.
function locate(frames, t) {
  let lo = 0, hi = frames.length - 1;
  if (t <= frames[0].t) return [0, 0];
  if (t >= frames[hi].t) return [hi, 0];
  while (hi - lo > 1) {
    const mid = (lo + hi) >> 1;
    if (frames[mid].t <= t) lo = mid; else hi = mid;
  }
  return [lo, (t - frames[lo].t) / (frames[lo + 1].t - frames[lo].t)];
}

// ---- scene ----
const view = $('view');
const renderer = new THREE.WebGLRenderer({antialias: true, preserveDrawingBuffer: true});
renderer.setPixelRatio(window.devicePixelRatio || 1);
view.appendChild(renderer.domElement);
const scene = new THREE.Scene();
scene.background = new THREE.Color(0xdde6ee);
const camera = new THREE.PerspectiveCamera(45, 1, 0.01, 200);
camera.up.set(0, 0, 1);
const controls = new OrbitControls(camera, renderer.domElement);
scene.add(new THREE.HemisphereLight(0xffffff, 0x445544, 2.2));
const sun = new THREE.DirectionalLight(0xffffff, 1.6);
sun.position.set(-3, -4, 8);
scene.add(sun);

function mat(colour, extra = {}) {
  return new THREE.MeshStandardMaterial(Object.assign({color: colour, roughness: 0.7}, extra));
}
function box(sx, sy, sz, material, x, y, z) {
  const m = new THREE.Mesh(new THREE.BoxGeometry(sx, sy, sz), material);
  m.position.set(x, y, z);
  return m;
}

function addField(f) {
  const carpet = new THREE.Mesh(new THREE.PlaneGeometry(f.carpet_length_m, f.carpet_width_m),
                                mat(0x3f9b4b));
  scene.add(carpet);
  const white = mat(0xffffff);
  const w = f.line_width_m, hx = f.field_length_m / 2, hy = f.field_width_m / 2, z = 0.0005;
  scene.add(box(f.field_length_m + w, w, 0.001, white, 0, hy, z));
  scene.add(box(f.field_length_m + w, w, 0.001, white, 0, -hy, z));
  scene.add(box(w, f.field_width_m + w, 0.001, white, hx, 0, z));
  scene.add(box(w, f.field_width_m + w, 0.001, white, -hx, 0, z));
  scene.add(box(w, f.field_width_m, 0.001, white, 0, 0, z));
  for (const side of [1, -1]) addGoal(f.goal, side);
}

// Posts up to the net's height, a crossbar, side nets, back net and roof (physics_scene.h).
function addGoal(g, side) {
  const post = mat(side > 0 ? 0xf2d600 : 0x1f5fbf);
  const h = g.net_height_m, r = g.post_radius_m;
  for (const y of [g.post_centre_y_m, -g.post_centre_y_m]) {
    const p = new THREE.Mesh(new THREE.CylinderGeometry(r, r, h, 24), post);
    p.rotation.x = Math.PI / 2;
    p.position.set(side * g.post_centre_x_m, y, h / 2);
    scene.add(p);
  }
  const bar = new THREE.Mesh(new THREE.CylinderGeometry(r, r, 2 * g.post_centre_y_m, 24), post);
  bar.position.set(side * g.post_centre_x_m, 0, h);
  scene.add(bar);
  const front = side * g.post_centre_x_m, back = side * (g.post_centre_x_m + g.net_depth_m);
  const yl = g.post_centre_y_m;
  const netMat = new THREE.MeshBasicMaterial({color: 0xffffff, transparent: true, opacity: 0.18,
                                              side: THREE.DoubleSide, depthWrite: false});
  const quads = [
    [[front, yl, 0], [back, yl, 0], [back, yl, h], [front, yl, h]],
    [[front, -yl, 0], [back, -yl, 0], [back, -yl, h], [front, -yl, h]],
    [[back, -yl, 0], [back, yl, 0], [back, yl, h], [back, -yl, h]],
    [[front, -yl, h], [back, -yl, h], [back, yl, h], [front, yl, h]],
  ];
  const mesh = [];
  const cell = 0.1;  // the drawn mesh of the net, m (drawing only)
  for (const q of quads) {
    const geo = new THREE.BufferGeometry();
    geo.setAttribute('position', new THREE.Float32BufferAttribute(
        [...q[0], ...q[1], ...q[2], ...q[0], ...q[2], ...q[3]], 3));
    scene.add(new THREE.Mesh(geo, netMat));
    const a = new THREE.Vector3(...q[0]), b = new THREE.Vector3(...q[1]);
    const c = new THREE.Vector3(...q[2]), d = new THREE.Vector3(...q[3]);
    const nu = Math.max(1, Math.round(a.distanceTo(b) / cell));
    const nv = Math.max(1, Math.round(a.distanceTo(d) / cell));
    for (let i = 0; i <= nu; ++i) {
      mesh.push(a.clone().lerp(b, i / nu), d.clone().lerp(c, i / nu));
    }
    for (let j = 0; j <= nv; ++j) {
      mesh.push(a.clone().lerp(d, j / nv), b.clone().lerp(c, j / nv));
    }
  }
  const lines = new THREE.BufferGeometry().setFromPoints(mesh);
  scene.add(new THREE.LineSegments(lines, new THREE.LineBasicMaterial(
      {color: 0xf4f4f4, transparent: true, opacity: 0.6})));
}

// One THREE.Group per URDF link, holding its collision shapes placed in the link frame.
function makeRobot(robot, colour, opacity) {
  const material = mat(colour, {transparent: opacity < 1, opacity, side: THREE.DoubleSide,
                                roughness: 0.5, metalness: 0.1});
  const footMaterial = mat(0x333333, {transparent: opacity < 1, opacity, side: THREE.DoubleSide});
  const m = 1e4;  // shapes come in the trace's position units
  return robot.links.map(link => {
    const group = new THREE.Group();
    group.name = link.name;
    for (const s of link.shapes) {
      let geo;
      if (s.box) {
        geo = new THREE.BoxGeometry(s.box[0] / m, s.box[1] / m, s.box[2] / m);
      } else if (s.sphere !== undefined) {
        geo = new THREE.SphereGeometry(s.sphere / m, 20, 14);
      } else if (s.cylinder) {
        geo = new THREE.CylinderGeometry(s.cylinder[0] / m, s.cylinder[0] / m, s.cylinder[1] / m, 20);
        geo.rotateX(Math.PI / 2);  // URDF cylinders lie along z, three.js's along y
      } else {
        geo = new THREE.BufferGeometry();
        geo.setAttribute('position',
                         new THREE.Float32BufferAttribute(s.vertices.map(v => v / m), 3));
        geo.setIndex(s.triangles);
        geo.computeVertexNormals();
      }
      const mesh = new THREE.Mesh(geo, s.vertices ? footMaterial : material);
      mesh.position.set(s.pose[0] / m, s.pose[1] / m, s.pose[2] / m);
      mesh.quaternion.set(s.pose[3], s.pose[4], s.pose[5], s.pose[6]).normalize();
      group.add(mesh);
    }
    scene.add(group);
    return group;
  });
}

function makeBall(radius, opacity, tint) {
  // Octants in two colours so that the spin shows.
  const geo = new THREE.SphereGeometry(radius, 32, 20);
  const pos = geo.attributes.position, colours = [];
  const a = new THREE.Color(0xffffff), b = new THREE.Color(tint);
  for (let i = 0; i < pos.count; ++i) {
    const odd = (pos.getX(i) > 0) ^ (pos.getY(i) > 0) ^ (pos.getZ(i) > 0);
    const c = odd ? b : a;
    colours.push(c.r, c.g, c.b);
  }
  geo.setAttribute('color', new THREE.Float32BufferAttribute(colours, 3));
  const ball = new THREE.Mesh(geo, mat(0xffffff, {vertexColors: true, transparent: opacity < 1,
                                                  opacity, roughness: 0.4}));
  scene.add(ball);
  return ball;
}

function makeBody(body) {
  const group = new THREE.Group();
  const colour = TEAM_COLOURS[body.team] || 0x777777;
  const cyl = new THREE.Mesh(
      new THREE.CylinderGeometry(body.radius_m, body.radius_m, body.height_m, 32), mat(colour));
  cyl.rotation.x = Math.PI / 2;
  cyl.position.z = body.height_m / 2;
  group.add(cyl);
  group.add(box(body.radius_m, 0.04, 0.04, mat(0xffffff), body.radius_m * 0.6, 0,
                body.height_m * 0.85));
  scene.add(group);
  return group;
}

addField(data.field);
for (const r of data.regions) {
  const w = r.x_max - r.x_min, h = r.y_max - r.y_min;
  const region = box(w, h, 0.002, mat(TEAM_COLOURS[r.team] || 0x777777,
                                       {transparent: true, opacity: 0.22}),
                     (r.x_min + r.x_max) / 2, (r.y_min + r.y_max) / 2, 0.001);
  scene.add(region);
}

const trials = data.trials.map((t, k) => {
  const tr = decodeTrace(t.trace);
  const colour = TRIAL_COLOURS[k % TRIAL_COLOURS.length];
  const path = new THREE.Line(new THREE.BufferGeometry().setFromPoints(tr.frames.map(f => f.ball)),
                              new THREE.LineBasicMaterial({color: colour}));
  scene.add(path);
  return Object.assign(tr, {label: t.label, numbers: t.numbers, events: t.events, colour, path,
                            ghost: makeBall(data.ball_radius_m, 0.45, colour)});
});
const ball = makeBall(data.ball_radius_m, 1, 0xff8c00);
const robot = data.robot ? makeRobot(data.robot, 0xe8e8ee, 1) : [];
const obstacleRobots = [];
const bodyMeshes = [];
const flashes = [];

// ---- state ----
// Overlaid by default when every trial is a kick; a match with its kicks shows one at a time.
const state = {trial: 0, t: 0, playing: false, speed: 1, target: null,
               overlay: !data.trials.some(t => t.trace.bodies.length > 0)};
const duration = () => state.overlay
    ? Math.max(...trials.map(tr => tr.frames[tr.frames.length - 1].t))
    : trials[state.trial].frames[trials[state.trial].frames.length - 1].t;

function pose(obj, a, b, s) {
  obj.position.copy(a.p).lerp(b.p, s);
  obj.quaternion.copy(a.q).slerp(b.q, s);
}

function placeTrial(tr, t, withRobot) {
  const [i, s] = locate(tr.frames, t);
  const f = tr.frames[i], g = tr.frames[Math.min(i + 1, tr.frames.length - 1)];
  const p = f.ball.clone().lerp(g.ball, s), q = f.ballQ.clone().slerp(g.ballQ, s);
  if (withRobot) {
    ball.position.copy(p);
    ball.quaternion.copy(q);
    if (f.links) {
      const next = g.links && g !== f ? g.links : f.links;
      robot.forEach((link, k) => pose(link, f.links[k], next[k], s));
    }
    robot.forEach(link => { link.visible = !!f.links; });
    if (f.bodies) {
      const next = g.bodies || f.bodies;
      f.bodies.forEach((b, k) => {
        const m = bodyMeshes[k];
        m.position.set(b.x + (next[k].x - b.x) * s, b.y + (next[k].y - b.y) * s, 0);
        m.rotation.z = b.h + Math.atan2(Math.sin(next[k].h - b.h), Math.cos(next[k].h - b.h)) * s;
      });
    }
  }
  tr.ghost.position.copy(p);
  tr.ghost.quaternion.copy(q);
  return f;
}

function showTrial(k) {
  state.trial = k;
  const tr = trials[k];
  obstacleRobots.forEach(o => o.forEach(l => scene.remove(l)));
  obstacleRobots.length = 0;
  for (const o of tr.obstacles) {
    const links = makeRobot(data.robot, 0x9a9aa6, 1);
    links.forEach((l, i) => { l.position.copy(o[i].p); l.quaternion.copy(o[i].q); });
    obstacleRobots.push(links);
  }
  bodyMeshes.forEach(m => scene.remove(m));
  bodyMeshes.length = 0;
  for (const b of tr.bodies) bodyMeshes.push(makeBody(b));
  $('numbers').innerHTML = '';
  for (const [key, value] of tr.numbers) {
    const row = $('numbers').insertRow();
    row.insertCell().textContent = key;
    row.insertCell().textContent = value;
  }
  $('events-box').hidden = tr.events.length === 0;
  $('trial').value = String(k);
  // A kick's scene is looked at from where the camera stands, moved to its ball.
  if (tr.frames[0].links) {
    const offset = camera.position.clone().sub(controls.target);
    if (tr.bodies.length === 0 && trials[0].bodies.length > 0) offset.set(-1.1, -1.3, 0.85);
    controls.target.copy(tr.frames[0].ball);
    camera.position.copy(tr.frames[0].ball).add(offset);
  }
  update();
}

function updateFlashes(tr, t) {
  flashes.forEach(m => scene.remove(m));
  flashes.length = 0;
  const max = Math.max(1e-9, ...tr.contacts.map(c => c.impulse));
  const list = $('contacts');
  list.innerHTML = '';
  const past = tr.contacts.filter(c => c.t <= t + 1e-9);
  for (const c of past.slice(-8).reverse()) {
    const li = document.createElement('li');
    const age = t - c.t;
    li.textContent = `${c.t.toFixed(3)} s  ${c.a} – ${c.b}  ${(c.impulse * 1000).toPrecision(3)} mN s`;
    if (age < FLASH_S) li.className = 'flash';
    list.appendChild(li);
    if (age >= FLASH_S) continue;
    const r = 0.008 + 0.04 * Math.sqrt(c.impulse / max);
    const m = new THREE.Mesh(new THREE.SphereGeometry(r, 16, 10), new THREE.MeshBasicMaterial(
        {color: 0xff2020, transparent: true, opacity: 0.9 * (1 - age / FLASH_S), depthTest: false}));
    m.position.copy(c.p);
    m.renderOrder = 10;
    scene.add(m);
    flashes.push(m);
  }
}

function update() {
  const tr = trials[state.trial];
  const t = state.t;
  const f = placeTrial(tr, t, true);
  trials.forEach((other, k) => {
    other.path.visible = state.overlay || k === state.trial;
    other.ghost.visible = state.overlay && k !== state.trial;
    if (other.ghost.visible) placeTrial(other, t, false);
  });
  updateFlashes(tr, t);
  $('time').textContent = `${t.toFixed(3)} s`;
  $('phase').textContent = tr.phases[f.phase] || '';
  $('slider').max = duration();
  $('slider').value = t;
  if (tr.events.length) {
    $('events').textContent = tr.events.filter(e => e[0] <= t + 1e-9)
        .map(e => `${e[0].toFixed(2).padStart(6)} s  ${e[1]}`).join('\n');
    $('events').scrollTop = $('events').scrollHeight;
  }
  if ($('follow').checked) controls.target.copy(ball.position);
}

// What the page shows, read back from its three.js objects (the browser test checks it).
function writeState() {
  const world = o => o.getWorldPosition(new THREE.Vector3()).toArray();
  const links = {};
  robot.forEach(l => { links[l.name] = world(l); });
  const out = {trial: state.trial, t: state.t, ball: world(ball), links,
               bodies: bodyMeshes.map(world)};
  $('state').textContent = JSON.stringify(out);
  document.title = `${data.title} [paused t=${state.t.toFixed(3)}]`;
}

function setPlaying(on) {
  state.playing = on;
  $('play').textContent = on ? 'pause' : '▶ play';
  if (!on) writeState();
}

function step(direction) {
  setPlaying(false);
  const frames = trials[state.trial].frames;
  const [i] = locate(frames, state.t);
  const exact = Math.abs(frames[i].t - state.t) < 1e-9;
  const j = direction > 0 ? Math.min(i + 1, frames.length - 1) : (exact ? Math.max(i - 1, 0) : i);
  state.t = frames[j].t;
  update();
  writeState();
}

// ---- controls ----
data.trials.forEach((t, k) => {
  const option = document.createElement('option');
  option.value = String(k);
  option.textContent = t.label;
  $('trial').appendChild(option);
});
$('trial').onchange = () => showTrial(+$('trial').value);
$('overlay').onchange = () => { state.overlay = $('overlay').checked; update(); };
$('play').onclick = () => {
  if (!state.playing && state.t >= duration()) state.t = 0;
  setPlaying(!state.playing);
};
$('back').onclick = () => step(-1);
$('forward').onclick = () => step(1);
$('speed').onchange = () => { state.speed = +$('speed').value; };
$('slider').oninput = () => { setPlaying(false); state.t = +$('slider').value; update(); writeState(); };
window.addEventListener('keydown', e => {
  if (e.target.tagName === 'SELECT' || e.target.tagName === 'INPUT' && e.target.type === 'range') return;
  if (e.key === ' ') { e.preventDefault(); $('play').onclick(); }
  if (e.key === 'ArrowRight') step(1);
  if (e.key === 'ArrowLeft') step(-1);
});
const about = $('about');
for (const [key, value] of data.about) {
  const row = about.insertRow();
  row.insertCell().textContent = key;
  row.insertCell().textContent = value;
}

function resize() {
  const w = view.clientWidth, h = view.clientHeight;
  renderer.setSize(w, h, false);
  camera.aspect = w / Math.max(h, 1);
  camera.updateProjectionMatrix();
}
window.addEventListener('resize', resize);

// The first view: from behind and left of the kick, or over the whole field for a match.
const first = trials[0].frames[0];
if (data.robot && trials[0].bodies.length === 0) {
  controls.target.copy(first.ball);
  camera.position.set(first.ball.x - 1.1, first.ball.y - 1.3, 0.9);
} else {
  camera.position.set(0, -data.field.field_width_m * 1.05, data.field.field_width_m * 0.9);
}
controls.update();

// Address: #trial=K&t=T (paused at T) or #trial=K&play=T (plays, pauses at T).
const hash = new URLSearchParams(location.hash.slice(1));
$('overlay').checked = state.overlay;
showTrial(Math.min(Math.max(+hash.get('trial') || 0, 0), trials.length - 1));
if (hash.has('t')) {
  state.t = Math.min(Math.max(+hash.get('t'), 0), duration());
  update();
  writeState();
} else if (hash.has('play')) {
  state.target = +hash.get('play');
  setPlaying(true);
} else {
  writeState();
}

// The clock runs on a timer, the drawing on animation frames: a browser that draws no frames
// (a hidden tab, headless chromium under --virtual-time-budget) still plays to its time.
let last = performance.now();
setInterval(() => {
  const now = performance.now();
  if (state.playing) {
    state.t += Math.min(0.1, (now - last) / 1000) * state.speed;
    if (state.target !== null && state.t >= state.target) {
      state.t = state.target;
      state.target = null;
      update();
      setPlaying(false);
    } else if (state.t >= duration()) {
      state.t = duration();
      update();
      setPlaying(false);
    } else {
      update();
    }
  }
  last = now;
}, 15);

function draw() {
  resize();
  controls.update();
  renderer.render(scene, camera);
  requestAnimationFrame(draw);
}
requestAnimationFrame(draw);
