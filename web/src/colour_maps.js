// The renderer's colour maps (src/render/colour_map.cpp), the same stops, for the shader and the
// colour bar. Values are display (sRGB-encoded) colours, as in the PNGs of 'isopatch render'.

export const DIVERGING = [
  [-1.0, [0.13, 0.27, 0.68]],
  [-0.5, [0.52, 0.68, 0.90]],
  [0.0, [1.0, 1.0, 1.0]],
  [0.5, [0.93, 0.58, 0.48]],
  [1.0, [0.70, 0.09, 0.15]],
];

export const SEQUENTIAL = [
  [0.0, [1.0, 1.0, 0.80]],
  [1.0 / 3.0, [0.99, 0.80, 0.38]],
  [2.0 / 3.0, [0.92, 0.36, 0.14]],
  [1.0, [0.50, 0.0, 0.10]],
];

const f = (x) => (Number.isInteger(x) ? x.toFixed(1) : String(x));
const vec3 = (c) => `vec3(${c.map(f).join(', ')})`;

// A GLSL function `vec3 name(float t)`: linear between the stops, saturating at both ends.
export function glslColourMap(name, stops) {
  let body = `  if (t <= ${f(stops[0][0])}) return ${vec3(stops[0][1])};\n`;
  for (let i = 1; i < stops.length; ++i) {
    const [t0, c0] = stops[i - 1];
    const [t1, c1] = stops[i];
    body += `  if (t <= ${f(t1)}) return mix(${vec3(c0)}, ${vec3(c1)}, (t - ${f(t0)}) / ${f(t1 - t0)});\n`;
  }
  body += `  return ${vec3(stops[stops.length - 1][1])};\n`;
  return `vec3 ${name}(float t) {\n${body}}\n`;
}

// The colour at t on `stops`, as CSS rgb().
export function cssColour(stops, t) {
  let c = stops[stops.length - 1][1];
  if (t <= stops[0][0]) c = stops[0][1];
  else
    for (let i = 1; i < stops.length; ++i)
      if (t <= stops[i][0]) {
        const s = (t - stops[i - 1][0]) / (stops[i][0] - stops[i - 1][0]);
        c = stops[i - 1][1].map((a, k) => a + s * (stops[i][1][k] - a));
        break;
      }
  return `rgb(${c.map((x) => Math.round(255 * x)).join(',')})`;
}

// Paints the bar of `stops` over [lo, hi] into a canvas.
export function paintBar(canvas, stops, lo, hi) {
  const g = canvas.getContext('2d');
  for (let x = 0; x < canvas.width; ++x) {
    const t = lo + ((hi - lo) * (x + 0.5)) / canvas.width;
    g.fillStyle = cssColour(stops, t);
    g.fillRect(x, 0, 1, canvas.height);
  }
}

// The renderer's robust range: the 98th percentile (nearest rank) of |v| over the defined values,
// else the largest |v|, else 1.
export function robustRange(values, undefinedValue, percentile = 98) {
  const m = [];
  for (const v of values) if (v > undefinedValue && Number.isFinite(v)) m.push(Math.abs(v));
  if (m.length === 0) return 1;
  m.sort((a, b) => a - b);
  const rank = Math.min(Math.max(Math.ceil((percentile / 100) * m.length), 1), m.length) - 1;
  const r = m[rank] > 0 ? m[rank] : m[m.length - 1];
  return r > 0 ? r : 1;
}
