// The viewer in a real browser: Debian's headless chromium (WebGL through SwiftShader) driven by
// playwright-core, against `isopatch view torus` (ISOPATCH_CLI). Run by ctest (label browser).
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync, mkdirSync } from 'node:fs';
import net from 'node:net';
import path from 'node:path';
import { chromium } from 'playwright-core';
import { startViewer } from './server.mjs';

let viewer;
let browser;
let page;
const pageErrors = [];

before(async () => {
  viewer = await startViewer(['torus']);
  browser = await chromium.launch({
    executablePath: process.env.ISOPATCH_CHROMIUM || '/usr/bin/chromium',
    args: ['--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--ignore-gpu-blocklist'],
  });
  page = await browser.newPage({ viewport: { width: 1280, height: 860 } });
  // Generous: the machine may be busy compiling while this runs (SwiftShader renders on the CPU).
  page.setDefaultTimeout(120000);
  page.setDefaultNavigationTimeout(120000);
  page.on('pageerror', (e) => pageErrors.push(String(e)));
  await page.goto(viewer.url);
  await page.waitForFunction(() => window.isopatch && window.isopatch.ready, null, { timeout: 120000 });
});

after(async () => {
  if (browser) await browser.close();
  if (viewer) {
    const { code, signal } = await viewer.stop();
    assert.equal(code, 0, `Ctrl-C (SIGINT) should stop isopatch view cleanly; it ended with ${code} ${signal}`);
  }
});

// Pixels of the WebGL canvas: how many differ from the background, and how many are reddish / bluish
// (the diverging map's two ends), and a coarse fingerprint to compare pictures.
async function pixels() {
  return page.evaluate(() => {
    const gl = document.querySelector('#view canvas');
    const c = document.createElement('canvas');
    c.width = gl.width;
    c.height = gl.height;
    const g = c.getContext('2d');
    g.drawImage(gl, 0, 0);
    const d = g.getImageData(0, 0, c.width, c.height).data;
    let foreground = 0, red = 0, blue = 0, sum = 0;
    for (let i = 0; i < d.length; i += 4) {
      const [r, gr, b] = [d[i], d[i + 1], d[i + 2]];
      if (Math.abs(r - 242) + Math.abs(gr - 242) + Math.abs(b - 242) > 12) foreground += 1;
      if (r > gr + 40 && r > b + 40) red += 1;
      if (b > r + 40 && b > gr + 10) blue += 1;
      sum += (r * 3 + gr * 5 + b * 7) * ((i / 4) % 97);
    }
    return { total: d.length / 4, foreground, red, blue, sum };
  });
}

async function waitForMesh(previousId) {
  await page.waitForFunction((id) => window.isopatch.meshId > id && document.querySelector('#status').dataset.state === 'ready',
    previousId, { timeout: 120000 });
}

test('the page loads and shows the torus with its mean curvature', async () => {
  assert.equal(await page.locator('#status').getAttribute('data-state'), 'ready');
  // The library's version, from GET /api/state (one version: project() in the top CMakeLists.txt).
  assert.match(await page.locator('#version').textContent(), /^\d+\.\d+\.\d+$/);
  assert.equal(await page.inputValue('#mode'), 'mean_curvature');
  const p = await pixels();
  assert.ok(p.foreground > 0.05 * p.total, `only ${p.foreground} of ${p.total} pixels show the mesh`);
  // H > 0 all over a torus of radii 1 and 0.4, largest outside: the diverging map's red half.
  assert.ok(p.red > 0.02 * p.total, `red pixels: ${p.red}`);
  assert.ok(!(await page.locator('#colour-bar').isHidden()), 'the colour bar is hidden');
  const vertices = await page.evaluate(() => window.isopatch.summary.vertices);
  assert.ok(vertices > 100);
  const stats = await page.locator('#stats').innerText();
  assert.match(stats, /valence 6/);
  assert.match(stats, /smallest angle/);
  assert.deepEqual(pageErrors, []);
});

test('toggling curvature changes the picture; Gaussian curvature takes both signs', async () => {
  await page.selectOption('#mode', 'shaded');
  const shaded = await pixels();
  assert.ok(await page.locator('#colour-bar').isHidden(), 'a colour bar without a field');
  await page.selectOption('#mode', 'mean_curvature');
  const mean = await pixels();
  assert.notEqual(mean.sum, shaded.sum, 'the picture did not change');
  assert.ok(mean.red > shaded.red + 0.01 * mean.total, `red pixels: ${mean.red} against ${shaded.red} shaded`);
  await page.selectOption('#mode', 'gaussian_curvature');
  const gauss = await pixels();
  assert.ok(gauss.blue > 0.005 * gauss.total, `the inner side has K < 0: blue pixels ${gauss.blue}`);
  assert.ok(gauss.red > 0.005 * gauss.total, `the outer side has K > 0: red pixels ${gauss.red}`);
  // A smaller range saturates more pixels.
  await page.fill('#range', String(Number(await page.inputValue('#range')) / 8));
  await page.dispatchEvent('#range', 'change');
  const narrow = await pixels();
  assert.ok(narrow.red + narrow.blue > gauss.red + gauss.blue, 'narrowing the range saturated nothing');
  for (const mode of ['isophotes', 'reflection', 'distance', 'shaded']) {
    await page.selectOption('#mode', mode);
    const p = await pixels();
    assert.ok(p.foreground > 0.05 * p.total, `${mode}: the mesh disappeared`);
  }
  await page.check('#wireframe');
  const wire = await pixels();
  assert.notEqual(wire.sum, shaded.sum, 'the wireframe did not change the picture');
  await page.uncheck('#wireframe');
});

test('typing a new formula re-meshes', async () => {
  const before = await page.evaluate(() => ({ id: window.isopatch.meshId, v: window.isopatch.summary.vertices }));
  await page.fill('#surface', 'x^2 + y^2 + z^2 - 1');
  await page.fill('#box', '-1.3, -1.3, -1.3, 1.3, 1.3, 1.3');
  await page.click('#mesh-button');
  await waitForMesh(before.id);
  const after = await page.evaluate(() => window.isopatch.summary);
  assert.equal(after.surface, 'x^2 + y^2 + z^2 - 1');
  assert.notEqual(after.vertices, before.v);
  assert.ok((await page.locator('#error').isHidden()), 'an error is shown');
  const p = await pixels();
  assert.ok(p.foreground > 0.05 * p.total);
});

test('a formula with creases is meshed along them, and the page says so', async () => {
  const before = await page.evaluate(() => window.isopatch.meshId);
  await page.fill('#surface', 'max(max(abs(x), abs(y)), abs(z)) - 1');
  await page.fill('#box', '-1.5, -1.5, -1.5, 1.5, 1.5, 1.5');
  await page.click('#mesh-button');
  await waitForMesh(before);
  const s = await page.evaluate(() => window.isopatch.summary);
  assert.deepEqual(s.creases && [s.creases.faces, s.creases.creases, s.creases.corners], [6, 12, 8]);
  assert.ok(s.min_angle >= 25, `smallest angle ${s.min_angle}`);
  assert.match(await page.locator('#stats').innerText(), /12 creases, 8 corners/);
  const p = await pixels();
  assert.ok(p.foreground > 0.05 * p.total);
});

test('a bad formula shows the error with its column, and the page lives on', async () => {
  const id = await page.evaluate(() => window.isopatch.meshId);
  await page.fill('#surface', 'x^2 + * y');
  await page.click('#mesh-button');
  await page.waitForSelector('#error:not([hidden])', { timeout: 120000 });
  const text = await page.locator('#error').innerText();
  // The parser stops at the '*' that has no left operand.
  assert.match(text, new RegExp(`column ${'x^2 + * y'.indexOf('*') + 1}\\b`));
  assert.equal(await page.evaluate(() => window.isopatch.meshId), id, 'the old mesh should stay');
  const p = await pixels();
  assert.ok(p.foreground > 0.05 * p.total, 'the old mesh is no longer drawn');
  await page.fill('#surface', 'torus');
  await page.fill('#box', '');
  await page.click('#mesh-button');
  await waitForMesh(id);
  assert.ok(await page.locator('#error').isHidden());
  if (process.env.ISOPATCH_SCREENSHOT) {
    await page.selectOption('#mode', 'mean_curvature');
    await page.check('#wireframe');
    mkdirSync(path.dirname(process.env.ISOPATCH_SCREENSHOT), { recursive: true });
    await page.screenshot({ path: process.env.ISOPATCH_SCREENSHOT });
  }
  assert.deepEqual(pageErrors, []);
});

test('the page downloads the mesh as GLB and PLY', async () => {
  const id = await page.evaluate(() => window.isopatch.meshId);
  const base = new URL(viewer.url);
  const glb = await fetch(new URL(`/api/mesh/${id}.glb`, base));
  assert.equal(glb.status, 200);
  const bytes = new Uint8Array(await glb.arrayBuffer());
  assert.equal(new TextDecoder().decode(bytes.slice(0, 4)), 'glTF');
  const ply = await fetch(new URL(await page.getAttribute('#download-ply', 'href'), base));
  assert.equal(ply.status, 200);
  assert.match(ply.headers.get('content-disposition'), /attachment/);
  assert.equal(new TextDecoder().decode(new Uint8Array(await ply.arrayBuffer()).slice(0, 3)), 'ply');
});

// One raw request line, so that nothing normalizes the path on the way.
function rawGet(port, target) {
  return new Promise((resolve, reject) => {
    const socket = net.connect(port, '127.0.0.1',
      () => socket.write(`GET ${target} HTTP/1.1\r\nHost: 127.0.0.1:${port}\r\nConnection: close\r\n\r\n`));
    let data = '';
    socket.on('data', (d) => { data += d; });
    socket.on('end', () => resolve(data));
    socket.on('error', reject);
  });
}

test('the server refuses paths outside what it serves', async () => {
  const port = Number(new URL(viewer.url).port);
  assert.match(await rawGet(port, '/main.js'), /^HTTP\/1.1 200/);
  for (const target of ['/../CMakeLists.txt', '/%2e%2e/%2e%2e/CMakeLists.txt', '/three/build/../../../package.json',
    '/three/build/..%2f..%2f..%2fpackage.json', '/..\\..\\CMakeLists.txt', '//etc/passwd', '/tests/viewer.test.mjs',
    '/node_modules/three/package.json', '/three/package.json']) {
    const answer = await rawGet(port, target);
    assert.match(answer, /^HTTP\/1.1 (400|404)/, `${target} was served: ${answer.slice(0, 80)}`);
    assert.doesNotMatch(answer, /cmake_minimum_required|"name"/);
  }
});

test('the server listens on loopback only', async () => {
  const port = Number(new URL(viewer.url).port);
  const hexPort = port.toString(16).toUpperCase().padStart(4, '0');
  const listening = readFileSync('/proc/net/tcp', 'utf8').split('\n').slice(1).map((l) => l.trim().split(/\s+/))
    .filter((f) => f.length > 3 && f[3] === '0A' && f[1].endsWith(':' + hexPort)).map((f) => f[1]);
  assert.deepEqual(listening, [`0100007F:${hexPort}`]);
  const tcp6 = readFileSync('/proc/net/tcp6', 'utf8');
  // The kernel's table of listening sockets: bound to 127.0.0.1 and nothing else (no packet is sent
  // to any other address to find out).
  const tcp6Listening = tcp6.split('\n').slice(1).map((l) => l.trim().split(/\s+/))
    .filter((f) => f.length > 3 && f[3] === '0A' && f[1].endsWith(':' + hexPort));
  assert.deepEqual(tcp6Listening, [], 'listening on IPv6 too');
});
