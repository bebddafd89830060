// The surface's shader: the renderer's Blinn-Phong light fixed to the camera (render.hpp, Lighting),
// the curvature and error colour maps on a per-vertex field, isophotes (stripes of the angle between
// normal and light) and reflection lines (stripes of the reflected view ray against parallel lines
// at infinity), all per pixel.
import * as THREE from 'three';
import { DIVERGING, SEQUENTIAL, glslColourMap } from './colour_maps.js';

export const MODES = { shaded: 0, diverging: 1, sequential: 2, isophotes: 3, reflection: 4 };
// What glTF holds where a field is undefined (mesh_io.hpp, kGlbUndefined = -FLT_MAX).
export const UNDEFINED = -3.0e38;

const vertexShader = `
attribute float field;
varying vec3 vNormal;
varying vec3 vView;
varying float vField;
void main() {
  vec4 p = modelViewMatrix * vec4(position, 1.0);
  vView = -p.xyz;
  vNormal = normalMatrix * normal;
  vField = field;
  gl_Position = projectionMatrix * p;
}`;

const fragmentShader = `
uniform int mode;
uniform float range;
uniform float stripes;
uniform vec3 lightDir;
uniform vec3 surfaceColour;
uniform vec3 backColour;
uniform vec3 missingColour;
uniform bool perspective;
varying vec3 vNormal;
varying vec3 vView;
varying float vField;
${glslColourMap('diverging', DIVERGING)}
${glslColourMap('sequential', SEQUENTIAL)}
const float PI = 3.14159265358979;
vec3 shaded(vec3 base, vec3 n, vec3 l) {
  vec3 h = normalize(l + vec3(0.0, 0.0, 1.0));
  float nh = max(dot(n, h), 0.0);
  return base * (0.25 + 0.75 * max(dot(n, l), 0.0)) + 0.25 * pow(nh, 40.0);
}
void main() {
  vec3 n = normalize(vNormal);
  if (!gl_FrontFacing) n = -n;
  vec3 l = normalize(lightDir);
  vec3 base = gl_FrontFacing ? surfaceColour : backColour;
  vec3 c;
  if (mode == 1 || mode == 2) {
    vec3 fc = missingColour;
    if (vField > -1.0e37) fc = mode == 1 ? diverging(vField / range) : sequential(abs(vField) / range);
    c = fc * (0.6 + 0.4 * max(dot(n, l), 0.0));
  } else if (mode == 3) {
    float angle = acos(clamp(dot(n, l), -1.0, 1.0));
    int k = int(min(floor(angle / PI * stripes), stripes - 1.0));
    c = shaded(base, n, l) * ((k % 2 == 0) ? 1.0 : 0.2);
  } else if (mode == 4) {
    vec3 v = perspective ? normalize(vView) : vec3(0.0, 0.0, 1.0);
    vec3 r = reflect(-v, n);
    // Lines at infinity parallel to the camera's x axis: the stripe is the angle of r about that axis.
    float phi = atan(r.y, r.z);
    float s = fract(phi / PI * stripes * 0.5);
    c = mix(vec3(0.08), vec3(0.97), step(0.5, s)) * (0.55 + 0.45 * max(dot(n, l), 0.0));
  } else {
    c = shaded(base, n, l);
  }
  gl_FragColor = vec4(clamp(c, 0.0, 1.0), 1.0);
}`;

export function makeSurfaceMaterial() {
  return new THREE.ShaderMaterial({
    vertexShader,
    fragmentShader,
    side: THREE.DoubleSide,
    polygonOffset: true, // the wireframe draws on top without fighting the surface
    polygonOffsetFactor: 1,
    polygonOffsetUnits: 1,
    uniforms: {
      mode: { value: MODES.shaded },
      range: { value: 1 },
      stripes: { value: 12 },
      lightDir: { value: new THREE.Vector3(-0.35, 0.45, 1.0) },
      surfaceColour: { value: new THREE.Vector3(0.72, 0.78, 0.88) },
      backColour: { value: new THREE.Vector3(0.92, 0.7, 0.5) },
      missingColour: { value: new THREE.Vector3(0.55, 0.55, 0.55) },
      perspective: { value: true },
    },
  });
}
