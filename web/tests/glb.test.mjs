// A .glb written by `isopatch mesh torus -o t.glb --fields` against the Khronos glTF validator (npm
// gltf-validator, an independent reader): no errors, and the fields are there, one value per vertex.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { mkdtempSync, readFileSync, rmSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import validator from 'gltf-validator';
import { cliPath } from './server.mjs';

// The JSON chunk and the BIN chunk of a GLB (glTF 2.0 specification, "Binary glTF layout").
function chunks(bytes) {
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  assert.equal(view.getUint32(0, true), 0x46546c67, 'magic glTF');
  assert.equal(view.getUint32(4, true), 2, 'version 2');
  assert.equal(view.getUint32(8, true), bytes.byteLength, 'declared length');
  const jsonLength = view.getUint32(12, true);
  const json = JSON.parse(new TextDecoder().decode(bytes.subarray(20, 20 + jsonLength)));
  const binLength = view.getUint32(20 + jsonLength, true);
  const bin = bytes.subarray(28 + jsonLength, 28 + jsonLength + binLength);
  return { json, bin };
}

function floats(gltf, bin, accessorIndex) {
  const a = gltf.accessors[accessorIndex];
  const v = gltf.bufferViews[a.bufferView];
  const components = { SCALAR: 1, VEC3: 3 }[a.type];
  const copy = bin.slice((v.byteOffset ?? 0) + (a.byteOffset ?? 0), (v.byteOffset ?? 0) + (a.byteOffset ?? 0) + 4 * components * a.count);
  return new Float32Array(copy.buffer);
}

test('isopatch mesh torus -o t.glb --fields is valid glTF and carries the fields', async () => {
  const dir = mkdtempSync(path.join(os.tmpdir(), 'isopatch-glb-'));
  try {
    const file = path.join(dir, 't.glb');
    execFileSync(cliPath(), ['mesh', 'torus', '-o', file, '--fields', '--quality', 'preview', '-q']);
    const bytes = new Uint8Array(readFileSync(file));
    const report = await validator.validateBytes(bytes);
    const problems = report.issues.messages.filter((m) => m.severity <= 1); // errors and warnings
    assert.deepEqual(problems, [], JSON.stringify(problems, null, 1));
    assert.equal(report.issues.numErrors, 0);

    const { json, bin } = chunks(bytes);
    assert.equal(json.meshes.length, 1);
    const primitive = json.meshes[0].primitives[0];
    const vertices = json.accessors[primitive.attributes.POSITION].count;
    assert.equal(report.info.totalVertexCount, vertices);
    for (const name of ['NORMAL', 'COLOR_0', '_MEAN_CURVATURE', '_MEAN_CURVATURE_EXACT', '_GAUSSIAN_CURVATURE',
      '_GAUSSIAN_CURVATURE_EXACT', '_DISTANCE']) {
      assert.ok(name in primitive.attributes, `${name} is missing`);
      assert.equal(json.accessors[primitive.attributes[name]].count, vertices, `${name}: one per vertex`);
    }
    // The colours are a map of the discrete mean curvature: linear RGB in [0, 1], not one colour.
    const colours = floats(json, bin, primitive.attributes.COLOR_0);
    assert.ok(colours.every((c) => c >= 0 && c <= 1));
    const reds = new Set(Array.from({ length: vertices }, (_, i) => colours[3 * i].toFixed(2)));
    assert.ok(reds.size > 10, `only ${reds.size} distinct colours`);
    // The exact mean curvature of a torus lies between those of its outer and inner equators:
    // a closed torus has every value finite, and both signs of the Gaussian curvature.
    const exact = floats(json, bin, primitive.attributes._GAUSSIAN_CURVATURE_EXACT);
    assert.ok(exact.some((k) => k > 0) && exact.some((k) => k < 0), 'K > 0 outside, K < 0 inside');
    const mean = floats(json, bin, primitive.attributes._MEAN_CURVATURE_EXACT);
    assert.ok(mean.every((h) => Number.isFinite(h) && h > -1e30));
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
});
