// Panel `angle-ratio`: one ray meets a flat interface and splits into a reflected part R and a
// refracted part T = 1 − R; stroke widths carry the powers. Past the critical angle (n₁ > n₂)
// nothing goes through. Numbers from src/optics/interfaceSplit.js (which uses fresnel.js).
import { interfaceSplit, interfaceSplitCurve } from '../optics/interfaceSplit.js';
import { cssVar } from '../ui/theme.js';
import { buildAngleRatioDiagram, svgToPng } from './angle-ratioDiagram.js';
import './angle-ratio.css';
import { el } from '../ui/el.js';

export const id = 'angle-ratio';
export const title = 'The ratio of reflection to refraction depends on the angle';
export const usesWebGL = false;
export const materialParam = 'n2';

export const schema = {
  theta: { type: 'number', default: 45, min: 0, max: 90, step: 0.1, label: 'Angle of incidence θ₁ (°)' },
  n1: { type: 'number', default: 1, min: 1, max: 3, step: 0.0001, label: 'n₁ (incident side)' },
  n2: { type: 'number', default: 1.5, min: 1, max: 3, step: 0.0001, label: 'n₂ (other side)' },
};

/** A labelled horizontal bar with its number; the bar itself is decoration (the number is text). */
function bar(label, className) {
  const row = el('div', `ar-bar-row ${className}`);
  const name = el('span', 'ar-bar-name', label);
  const track = el('span', 'ar-bar-track');
  const fill = el('span', 'ar-bar-fill');
  track.setAttribute('aria-hidden', 'true');
  track.append(fill);
  const value = el('span', 'ar-bar-value');
  row.append(name, track, value);
  return {
    row,
    set(v) {
      fill.style.width = `${(100 * v).toFixed(2)}%`;
      value.textContent = v.toFixed(4);
    },
  };
}

export function mount(root, ctx) {
  const { values } = ctx;
  const panel = el('div', 'angle-ratio-panel');
  const figure = el('div', 'ar-figure');
  const diagram = buildAngleRatioDiagram(figure, {
    onAngle(deg) {
      const next = Math.round(deg * 10) / 10;
      if (next === values.theta) return;
      values.theta = next;
      ctx.changed(['theta']);
    },
  });
  const bars = el('div', 'ar-bars');
  const rBar = bar('Reflected R', 'ar-bar-r');
  const tBar = bar('Transmitted T = 1 − R', 'ar-bar-t');
  bars.append(rBar.row, tBar.row);
  const status = el('p', 'ar-status');
  status.setAttribute('aria-live', 'polite');
  const analogy = el('p', 'ar-analogy',
    'Think of skipping a stone: the flatter it meets the water, the more likely it bounces off instead of '
    + 'going in, and light arriving at a grazing angle likewise mostly reflects.');
  panel.append(figure, bars, status, analogy);
  root.append(panel);

  const folder = ctx.gui.addFolder('Interface (or drag the incident ray / arrow keys)');
  ctx.bind(folder, ['theta', 'n1', 'n2']);
  folder.add({ swap: () => { [values.n1, values.n2] = [values.n2, values.n1]; ctx.changed(['n1', 'n2']); } }, 'swap')
    .name('Swap n₁ ↔ n₂ (light leaving the denser side)');

  let split = null;
  let pngUrl = null;
  let pngTimer = 0;
  let disposed = false;

  // The PNG export needs an image decode (asynchronous), so a fresh copy is prepared shortly after
  // each change and handed out by png().
  function refreshPng() {
    clearTimeout(pngTimer);
    pngTimer = setTimeout(() => {
      svgToPng(diagram.svg, cssVar('--panel', '#161b22'))
        .then((url) => { if (!disposed) pngUrl = url; })
        .catch(() => { pngUrl = null; });
    }, 250);
  }

  function update() {
    const { theta, n1, n2 } = values;
    split = interfaceSplit(theta, n1, n2);
    diagram.set(split, n1, n2);
    rBar.set(split.R);
    tBar.set(split.T);
    const critical = split.critical === null
      ? `No critical angle: light enters a denser (or equal) medium (n₁ ≤ n₂).`
      : `Critical angle ${split.critical.toFixed(2)}°.`;
    status.textContent = split.tir
      ? `Total internal reflection: ${theta.toFixed(1)}° is past the critical angle ${split.critical.toFixed(2)}°, `
        + 'so there is no refracted ray and T = 0; all the light is reflected.'
      : `θ₁ = ${theta.toFixed(1)}°, θ₂ = ${split.thetaT.toFixed(2)}° (Snell's law). ${critical}`;
    panel.classList.toggle('ar-is-tir', split.tir);
    refreshPng();
  }
  update();

  return {
    diagram,
    get split() { return split; },
    update,
    describe() {
      const { theta, n1, n2 } = values;
      const base = `From n₁ = ${n1} into n₂ = ${n2} at ${theta.toFixed(1)}° from the normal: `
        + `R = ${split.R.toFixed(4)} is reflected and T = ${split.T.toFixed(4)} is transmitted`;
      return split.tir
        ? `${base}; past the critical angle ${split.critical.toFixed(2)}° there is no refracted ray.`
        : `${base}, refracted to ${split.thetaT.toFixed(2)}°.`;
    },
    csv() {
      const { theta, R, T } = interfaceSplitCurve(values.n1, values.n2);
      return { filename: `angle-ratio-n1${values.n1}-n2${values.n2}.csv`, columns: { theta_deg: theta, R, T } };
    },
    png: () => pngUrl,
    dispose() {
      disposed = true;
      clearTimeout(pngTimer);
      diagram.dispose();
      panel.remove();
    },
  };
}
