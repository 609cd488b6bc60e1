// Texel inspector of the normal-mips panel: for texel (i, j) of a mip level, the level-0 slopes
// b = (n_x/n_z, n_y/n_z) its footprint covers (a 2D scatter, the true NDF in slope space) and the
// one lobe each technique fits to them, as its 1-σ contour: centre = the shading normal's slope,
// per-axis σ = α′/√2 for the isotropic lobes (v = α′²/2, the per-axis slope variance of a Beckmann
// lobe) and LEAN's covariance ellipse (leanCovariance, base lobe included). Lobes come from texelLobe (effectiveRoughness.js).
import english from 'virtual:messages/en/normal-mips';
import { messages } from '../../i18n/messages.js';
import { el } from '../../ui/el.js';
import { fixed } from '../../ui/format.js';
import { context2d } from '../../ui/context2d.js';
import { createLobe, texelLobe } from '../../normals/effectiveRoughness.js';
import { TECHNIQUES } from '../../normals/techniqueLayout.js';
import { cssVar, lineScale } from '../../ui/theme.js';
import { TECHNIQUE_STYLES } from './techniqueStyles.js';
import { techniqueName } from './techniqueName.js';

const t = messages('normal-mips', english);

const SIZE = 360;
const MAX_POINTS = 4096;

/** The level-0 slopes under texel (i, j) of `level` (pyramid[0] holds bx, by at offsets 3, 4), at most MAX_POINTS. */
export function footprintSlopes(pyramid, level, i, j) {
  const { size, data } = pyramid[0];
  const side = 2 ** level;
  const stride = Math.max(1, Math.ceil(side / Math.sqrt(MAX_POINTS)));
  const points = [];
  for (let y = j * side; y < (j + 1) * side; y += stride) {
    for (let x = i * side; x < (i + 1) * side; x += stride) {
      const o = ((y % size) * size + (x % size)) * 8;
      points.push([data[o + 3], data[o + 4]]);
    }
  }
  return points;
}

export function buildInspector(host) {
  const root = el('div', 'nm-inspector');
  root.append(el('h3', 'nm-strip-title', t('inspector.title')));
  const canvas = el('canvas', 'nm-inspector-canvas');
  canvas.width = SIZE;
  canvas.height = SIZE;
  const g = context2d(canvas); // claimed now: see context2d.js
  canvas.setAttribute('role', 'img');
  canvas.setAttribute('aria-label', t('inspector.canvasEmpty'));
  const side = el('div', 'nm-inspector-side');
  const keyList = el('ul', 'nm-inspector-key');
  const verdict = el('p', 'nm-inspector-verdict');
  verdict.setAttribute('aria-live', 'polite');
  side.append(keyList, verdict);
  const body = el('div', 'nm-inspector-body');
  body.append(canvas, side);
  root.append(body);
  host.append(root);

  let last = null; // the texel drawn last, redrawn in the colours of a new theme
  const onTheme = () => { if (last) inspector.draw(last); };
  window.addEventListener('fresnel-lab:theme', onTheme);
  const inspector = {
    /** Draws texel (i, j) of `level`; returns { points, lobes: { technique: { centre, alpha, covariance } }, bimodal }. */
    draw(at) {
      last = at;
      const { pyramid, chains, level, i, j, alpha, mapKind } = at;
      const levelSize = chains.naive.levels[level].size;
      const texel = j * levelSize + i;
      const points = footprintSlopes(pyramid, level, i, j);
      const lobes = {};
      for (const id of TECHNIQUES) {
        const lobe = texelLobe(chains[id], level, texel, { alpha }, createLobe());
        const [nx, ny, nz] = lobe.normal;
        lobes[id] = { centre: [nx / nz, ny / nz], alpha: lobe.alpha, covariance: lobe.covariance };
      }
      let extent = 0.2;
      for (const [x, y] of points) extent = Math.max(extent, Math.abs(x), Math.abs(y));
      extent *= 1.35;
      if (!g) return null;
      const toPx = (x, y) => [SIZE / 2 + (x / extent) * (SIZE / 2), SIZE / 2 - (y / extent) * (SIZE / 2)];
      g.fillStyle = cssVar('--bg', '#111');
      g.fillRect(0, 0, SIZE, SIZE);
      g.strokeStyle = cssVar('--border', '#555');
      g.lineWidth = 1;
      g.beginPath();
      g.moveTo(0, SIZE / 2); g.lineTo(SIZE, SIZE / 2); g.moveTo(SIZE / 2, 0); g.lineTo(SIZE / 2, SIZE);
      g.stroke();
      g.lineWidth = 3 * lineScale();
      for (const id of TECHNIQUES) {
        const { centre, alpha: a, covariance: c } = lobes[id];
        let rx = a / Math.SQRT2;
        let ry = rx;
        let angle = 0;
        if (c) { // principal axes of LEAN's Σ
          angle = 0.5 * Math.atan2(2 * c.sxy, c.sxx - c.syy);
          rx = Math.sqrt(c.major);
          ry = Math.sqrt(Math.max(c.minor, 0));
        }
        const [cx, cy] = toPx(centre[0], centre[1]);
        g.strokeStyle = cssVar(TECHNIQUE_STYLES[id].stroke);
        g.setLineDash(TECHNIQUE_STYLES[id].dash ?? []);
        g.beginPath();
        g.ellipse(cx, cy, (rx / extent) * (SIZE / 2), (ry / extent) * (SIZE / 2), -angle, 0, 2 * Math.PI);
        g.stroke();
      }
      // The true normals on top, as large dots: many coincide (facets), so they must not hide under a lobe.
      g.fillStyle = '#ffeb3b';
      g.setLineDash([]);
      g.strokeStyle = '#000';
      g.lineWidth = 1.5;
      for (const [x, y] of points) {
        const [px, py] = toPx(x, y);
        g.beginPath();
        g.arc(px, py, 5, 0, 2 * Math.PI);
        g.fill();
        g.stroke();
      }
      // Bimodal: the footprint's normals sit in clusters away from the fitted centre (V-grooves, checker facets).
      const cx = points.reduce((s, p) => s + p[0], 0) / points.length;
      const cy = points.reduce((s, p) => s + p[1], 0) / points.length;
      const spread = Math.sqrt(points.reduce((s, p) => s + (p[0] - cx) ** 2 + (p[1] - cy) ** 2, 0) / points.length);
      const near = points.filter((p) => Math.hypot(p[0] - cx, p[1] - cy) < 0.25 * spread).length / points.length;
      const bimodal = (mapKind === 'grooves' || mapKind === 'checker') && spread > 1e-3 && near < 0.05;
      keyList.replaceChildren(
        el('li', 'nm-key-points', t('inspector.points', {
          count: points.length, n: String(points.length), i: String(i), j: String(j), level: String(level),
        })),
        ...TECHNIQUES.map((id) => {
          const item = el('li', '', t('inspector.lobe', { technique: techniqueName(id), alpha: fixed(lobes[id].alpha, 3) }));
          item.style.borderLeftColor = `var(${TECHNIQUE_STYLES[id].stroke})`;
          return item;
        }),
      );
      verdict.textContent = t(bimodal ? 'inspector.bimodal' : spread < 1e-3 ? 'inspector.agree' : 'inspector.cloud');
      canvas.setAttribute('aria-label', t('inspector.canvas', {
        i: String(i), j: String(j), level: String(level), verdict: verdict.textContent,
      }));
      return { points, lobes, bimodal };
    },
    dispose() {
      window.removeEventListener('fresnel-lab:theme', onTheme);
    },
  };
  return inspector;
}
