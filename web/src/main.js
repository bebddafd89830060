// The page of 'isopatch view': the mesh the server shows (GLB with its fields as custom attributes),
// looked at through the shader of surface_material.js; the form re-meshes through POST /api/mesh.
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';
import { DIVERGING, SEQUENTIAL, paintBar, robustRange } from './colour_maps.js';
import { MODES, UNDEFINED, makeSurfaceMaterial } from './surface_material.js';
import { requestMesh, fetchState } from './api.js';

const $ = (id) => document.getElementById(id);
const view = $('view');
const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
renderer.setPixelRatio(window.devicePixelRatio);
renderer.setClearColor(new THREE.Color(0.95, 0.95, 0.95));
view.appendChild(renderer.domElement);
const scene = new THREE.Scene();
const camera = new THREE.PerspectiveCamera(30, 1, 0.01, 100);
const controls = new OrbitControls(camera, renderer.domElement);
const material = makeSurfaceMaterial();
const wireMaterial = new THREE.LineBasicMaterial({ color: 0x1a1a24 });
let surface = null; // THREE.Mesh
let wire = null; // THREE.LineSegments
let fieldRange = 1; // the range shown now
const state = { meshId: 0, summary: null, ready: false, renders: 0 };
window.isopatch = state; // for the browser tests and the curious

function resize() {
  const w = view.clientWidth;
  const h = view.clientHeight;
  renderer.setSize(w, h, false);
  camera.aspect = w / Math.max(h, 1);
  camera.updateProjectionMatrix();
}
window.addEventListener('resize', () => { resize(); draw(); });

function draw() {
  renderer.render(scene, camera);
  state.renders += 1;
}
controls.addEventListener('change', draw);

// The renderer's default view: azimuth 30, elevation 25 degrees about isopatch's z (glTF's y).
function frame(sphere) {
  const a = THREE.MathUtils.degToRad(30);
  const e = THREE.MathUtils.degToRad(25);
  const dir = new THREE.Vector3(Math.cos(e) * Math.cos(a), Math.sin(e), -Math.cos(e) * Math.sin(a));
  const distance = sphere.radius / Math.sin(THREE.MathUtils.degToRad(camera.fov / 2)) * 1.05;
  camera.position.copy(sphere.center).addScaledVector(dir, distance);
  camera.near = distance / 100;
  camera.far = distance * 10;
  camera.updateProjectionMatrix();
  controls.target.copy(sphere.center);
  controls.update();
}

// The attribute GLTFLoader made of the custom attribute `_NAME` (it lowercases unknown names).
function fieldAttribute(name) {
  return surface ? surface.geometry.getAttribute('_' + name) : undefined;
}

function currentField() {
  const mode = $('mode').value;
  if (mode === 'mean_curvature' || mode === 'gaussian_curvature')
    return $('exact').checked && fieldAttribute(mode + '_exact') ? mode + '_exact' : mode;
  if (mode === 'distance') return 'distance';
  return null;
}

function updateLook(resetRange) {
  const mode = $('mode').value;
  const field = currentField();
  const u = material.uniforms;
  u.stripes.value = Number($('stripes').value);
  $('stripes-value').textContent = $('stripes').value;
  const attribute = field ? fieldAttribute(field) : undefined;
  if (field && !attribute) {
    showError(`this mesh has no field '${field}' (a mesh file shows discrete curvature only; give --surface)`);
  }
  if (attribute && surface) {
    surface.geometry.setAttribute('field', attribute);
    if (resetRange || !Number.isFinite(fieldRange)) fieldRange = robustRange(attribute.array, UNDEFINED);
    const typed = Number($('range').value);
    if (!resetRange && Number.isFinite(typed) && typed > 0) fieldRange = typed;
    $('range').value = fieldRange.toPrecision(3);
    u.range.value = fieldRange;
    u.mode.value = field === 'distance' ? MODES.sequential : MODES.diverging;
    const sequential = field === 'distance';
    paintBar($('colour-bar-canvas'), sequential ? SEQUENTIAL : DIVERGING, sequential ? 0 : -1, 1);
    $('bar-lo').textContent = sequential ? '0' : (-fieldRange).toPrecision(3);
    $('bar-mid').textContent = sequential ? (fieldRange / 2).toPrecision(3) : '0';
    $('bar-hi').textContent = fieldRange.toPrecision(3);
    $('colour-bar').hidden = false;
    $('range-row').hidden = false;
  } else {
    u.mode.value = mode === 'isophotes' ? MODES.isophotes : mode === 'reflection' ? MODES.reflection : MODES.shaded;
    $('colour-bar').hidden = true;
    $('range-row').hidden = true;
  }
  if (wire) wire.visible = $('wireframe').checked;
  draw();
}

function setStatus(text, kind) {
  $('status').textContent = text;
  $('status').dataset.state = kind;
}

function showError(message) {
  $('error').textContent = message;
  $('error').hidden = !message;
}

function showStats(s) {
  const rows = [
    ['surface', s.name],
    ['vertices', s.vertices.toLocaleString('en')],
    ['triangles', s.triangles.toLocaleString('en')],
    ['time', s.seconds !== undefined ? `${s.seconds.toFixed(3)} s (${s.quality})` : 'read from file'],
    ['valence 6', s.valence_6 === null ? '-' : `${(100 * s.valence_6).toFixed(1)} %`],
    ['smallest angle', s.min_angle === null ? '-' : `${s.min_angle.toFixed(1)}\u00b0`],
  ];
  // A formula with creases (min, max, abs) is meshed along them: say how many.
  if (s.creases) rows.push(['creases', `${s.creases.creases} creases, ${s.creases.corners} corners, ${s.creases.faces} faces`]);
  $('stats').replaceChildren(...rows.map(([k, v]) => {
    const tr = document.createElement('tr');
    for (const text of [k, v]) tr.appendChild(document.createElement('td')).textContent = text;
    return tr;
  }));
}

const loader = new GLTFLoader();
async function loadMesh(id, summary) {
  const gltf = await loader.loadAsync(`/api/mesh/${id}.glb`);
  let found = null;
  gltf.scene.traverse((o) => { if (o.isMesh && !found) found = o; });
  if (!found) throw new Error('the GLB holds no mesh');
  if (surface) {
    scene.remove(surface);
    surface.geometry.dispose();
  }
  if (wire) {
    scene.remove(wire);
    wire.geometry.dispose();
  }
  found.updateWorldMatrix(true, false);
  const geometry = found.geometry.clone().applyMatrix4(found.matrixWorld); // z up -> y up, baked in
  if (!geometry.getAttribute('field'))
    geometry.setAttribute('field', new THREE.Float32BufferAttribute(new Float32Array(geometry.getAttribute('position').count), 1));
  surface = new THREE.Mesh(geometry, material);
  wire = new THREE.LineSegments(new THREE.WireframeGeometry(geometry), wireMaterial);
  scene.add(surface, wire);
  geometry.computeBoundingSphere();
  const newSurface = !state.summary || state.summary.name !== summary.name;
  if (newSurface || !state.ready) frame(geometry.boundingSphere);
  state.meshId = id;
  state.summary = summary;
  $('download-glb').href = `/api/mesh/${id}.glb?download=1`;
  $('download-ply').href = `/api/mesh/${id}.ply?download=1`;
  showStats(summary);
  updateLook(true);
}

function fillForm(s) {
  if (s.surface !== undefined) $('surface').value = s.surface;
  else if (s.file) $('surface').placeholder = `(the file ${s.name}; type a formula to mesh instead)`;
  if (s.box) $('box').value = s.box.map((x) => +x.toPrecision(6)).join(', ');
  if (s.quality) $('quality').value = s.quality;
}

function numberOrNull(id) {
  const text = $(id).value.trim();
  if (text === '') return null;
  const x = Number(text);
  if (!Number.isFinite(x)) throw new Error(`${id.replace('-', ' ')}: '${text}' is not a number`);
  return x;
}

let latest = 0; // the newest request sent; answers to older ones are dropped
async function remesh() {
  const mine = ++latest;
  let body;
  try {
    const boxText = $('box').value.trim();
    const box = boxText === '' ? null : boxText.split(/[\s,]+/).map(Number);
    body = {
      surface: $('surface').value, box, quality: $('quality').value, method: $('method').value,
      edge_length: numberOrNull('edge-length'), max_error: numberOrNull('max-error'), remesh: numberOrNull('remesh'),
    };
  } catch (e) {
    showError(e.message);
    setStatus('not sent', 'error');
    return;
  }
  setStatus('meshing...', 'busy');
  try {
    const answer = await requestMesh(body);
    if (mine !== latest || answer.superseded) return;
    if (answer.error) {
      const e = answer.error;
      let text = e.error;
      if (e.column !== undefined) text = `column ${e.column}: ${e.error}\n${e.excerpt}`;
      showError(text);
      setStatus(`error (${e.kind})`, 'error');
      return;
    }
    showError('');
    await loadMesh(answer.id, answer.summary);
    if (mine === latest) setStatus(`mesh ${answer.id} shown`, 'ready');
  } catch (e) {
    if (mine !== latest) return;
    showError(`the server did not answer: ${e.message}`);
    setStatus('error (network)', 'error');
  }
}

let typing = null;
$('mesh-form').addEventListener('submit', (e) => { e.preventDefault(); clearTimeout(typing); remesh(); });
$('surface').addEventListener('keydown', (e) => {
  if (e.key === 'Enter' && (e.ctrlKey || e.metaKey)) { e.preventDefault(); clearTimeout(typing); remesh(); }
});
$('surface').addEventListener('input', () => {
  clearTimeout(typing);
  if ($('live').checked) typing = setTimeout(remesh, 700);
});
for (const id of ['mode', 'exact']) $(id).addEventListener('change', () => updateLook(true));
$('wireframe').addEventListener('change', () => updateLook(false));
$('stripes').addEventListener('input', () => updateLook(false));
$('range').addEventListener('change', () => updateLook(false));
$('range-auto').addEventListener('click', () => updateLook(true));

async function start() {
  resize();
  try {
    const { id, summary, version } = await fetchState();
    // The library's version (project() in the top CMakeLists.txt), as the server was built with it.
    if (version) $('version').textContent = version;
    if (id > 0) {
      fillForm(summary);
      await loadMesh(id, summary);
      setStatus(`mesh ${id} shown`, 'ready');
    } else {
      setStatus('no mesh yet: type a surface', 'ready');
    }
  } catch (e) {
    showError(`could not load the mesh: ${e.message}`);
    setStatus('error', 'error');
  }
  state.ready = true;
}
start();
