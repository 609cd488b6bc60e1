// The mip strip of the normal-mips panel: every level of the chain three ways (2D canvases):
//   RGB       the stored average N_a as the colour c = N_a/2 + ½ (naive chain)
//   |N_a|     its length as a heatmap over [0.5, 1] (1 = all normals agree; Toksvig's input,
//             Toksvig, "Mipmapping Normal Maps", NVIDIA 2004)
//   α'        the chosen technique's effective roughness (effectiveRoughness.js texelLobe) over [0, 1]
// and the storage cost of every technique's chain (storageCost.js). Heat colours: src/ui/colormap.js.
import english from 'virtual:messages/en/normal-mips';
import { messages } from '../../i18n/messages.js';
import { colormap, colormapGradient } from '../../ui/colormap.js';
import { el } from '../../ui/el.js';
import { fixed } from '../../ui/format.js';
import { context2d } from '../../ui/context2d.js';
import { createLobe, texelLobe } from '../../normals/effectiveRoughness.js';
import { reconstructZ } from '../../normals/lobeFormulas.js';
import { storageCost } from '../../normals/storageCost.js';
import { TECHNIQUES } from '../../normals/techniqueLayout.js';
import { makeScrollBox } from '../../ui/scrollBox.js';
import { techniqueName } from './techniqueName.js';

const t = messages('normal-mips', english);

const CELL = 84; // CSS pixels per level thumbnail
const LUT = Array.from({ length: 256 }, (_, i) => colormap(i / 255).map((v) => Math.round(v * 255)));

function heat(t) {
  return LUT[Math.round(255 * Math.min(1, Math.max(0, t))) || 0];
}

// Thumbnails are drawn from at most THUMB² texels of a level, one per canvas pixel (the nearest
// texel, which is what drawing the full level without smoothing would show): a 1024² level costs
// no more than an 84² one, so the strip stays cheap at any map size.
const THUMB = CELL;

// One level into a thumbnail canvas: pixel(t) gives [r, g, b] bytes for texel t of a size² level.
function paint(canvas, size, pixel) {
  const m = Math.min(size, THUMB);
  const image = new ImageData(m, m);
  for (let y = 0; y < m; y++) {
    // Row 0 of the data is v = 0: draw it at the bottom, as on the plane's texture.
    const j = Math.floor(((m - 1 - y + 0.5) * size) / m);
    for (let x = 0; x < m; x++) {
      const [r, g, b] = pixel(j * size + Math.floor(((x + 0.5) * size) / m));
      const o = (y * m + x) * 4;
      image.data[o] = r;
      image.data[o + 1] = g;
      image.data[o + 2] = b;
      image.data[o + 3] = 255;
    }
  }
  const source = new OffscreenCanvas(m, m);
  source.getContext('2d').putImageData(image, 0, 0);
  const g = context2d(canvas);
  if (!g) return;
  g.imageSmoothingEnabled = false;
  g.clearRect(0, 0, canvas.width, canvas.height);
  g.drawImage(source, 0, 0, canvas.width, canvas.height);
}

/**
 * Mean |N_a| of a level of the naive chain over all its texels, z rebuilt for 2 channels as the
 * shader does (texelLobe's length, in one tight loop: a 1024² chain has 1.4 million texels).
 */
function meanStoredLength(chain, level) {
  const d = chain.levels[level].data;
  const c = chain.components;
  let sum = 0;
  for (let o = 0; o < d.length; o += c) {
    const x = d[o];
    const y = d[o + 1];
    const z = chain.channels === 3 ? d[o + 2] : Math.fround(reconstructZ(x, y));
    sum += Math.fround(Math.sqrt(x * x + y * y + z * z));
  }
  return sum / (d.length / c);
}

export function buildMipStrip(host, { onPick } = {}) {
  const root = makeScrollBox(el('div', 'nm-strip'), t('strip.title'));
  const heading = el('h3', 'nm-strip-title', t('strip.title'));
  const grid = el('div', 'nm-strip-grid');
  const legend = el('div', 'nm-strip-legend');
  const bar = el('span', 'nm-legend-bar');
  bar.style.background = colormapGradient();
  legend.append(el('span', '', t('strip.legend')), bar);
  const costs = el('table', 'nm-costs');
  root.append(heading, grid, legend, costs);
  host.append(root);
  let cells = [];

  function layout(levels) {
    grid.replaceChildren();
    cells = [];
    const rows = [t('strip.rowRgb'), t('strip.rowLength'), t('strip.rowAlpha')];
    // Cells shrink (down to 40 px) so that all 11 levels of a 1024² map fit beside each other.
    grid.style.gridTemplateColumns = `auto repeat(${levels}, minmax(40px, ${CELL}px))`;
    grid.append(el('span', 'nm-strip-row', t('strip.level')));
    for (let l = 0; l < levels; l++) grid.append(el('span', 'nm-strip-head', String(l)));
    rows.forEach((name, r) => {
      grid.append(el('span', 'nm-strip-row', name));
      cells[r] = [];
      for (let l = 0; l < levels; l++) {
        const canvas = el('canvas', 'nm-strip-cell');
        canvas.width = CELL;
        canvas.height = CELL;
        context2d(canvas); // claimed now, before its first picture: see context2d.js
        canvas.setAttribute('role', 'img');
        canvas.setAttribute('aria-label', t('strip.cell', { row: name, level: String(l) }));
        // A click picks that texel for the inspector (the inspector's sliders do the same from the keyboard).
        canvas.addEventListener('click', (event) => {
          const size = Math.max(1, cells.size >> l);
          const rect = canvas.getBoundingClientRect();
          const i = Math.min(size - 1, Math.floor(((event.clientX - rect.left) / rect.width) * size));
          const j = Math.min(size - 1, Math.floor((1 - (event.clientY - rect.top) / rect.height) * size));
          onPick?.(l, i, j);
        });
        grid.append(canvas);
        cells[r].push(canvas);
      }
    });
  }

  return {
    /** chains from buildAllChains; technique and base α pick the α′ row. Returns the level-wise mean |N_a|. */
    draw(chains, technique, alpha, { precision, precisionName = precision, channels }) {
      const naive = chains.naive;
      const levels = naive.levels.length;
      if (cells[0]?.length !== levels) layout(levels);
      cells.size = naive.size;
      const meanLength = [];
      const lobe = createLobe();
      const base = { alpha };
      const byte = (x) => Math.round(255 * Math.min(1, Math.max(0, x * 0.5 + 0.5)));
      naive.levels.forEach(({ size }, l) => {
        paint(cells[0][l], size, (t) => {
          const { normal: [x, y, z], length } = texelLobe(naive, l, t, base, lobe);
          return [byte(x * length), byte(y * length), byte(z * length)];
        });
        paint(cells[1][l], size, (t) => heat((texelLobe(naive, l, t, base, lobe).length - 0.5) / 0.5));
        paint(cells[2][l], size, (t) => heat(texelLobe(chains[technique], l, t, base, lobe).alpha));
        meanLength.push(meanStoredLength(naive, l));
      });
      const caption = t('cost.caption', { size: String(naive.size), precision: precisionName, channels: Number(channels) });
      costs.replaceChildren(el('caption', '', caption));
      const head = el('tr');
      head.append(...['cost.technique', 'cost.kib', 'cost.scalars', 'cost.keeps'].map((key) => el('th', '', t(key))));
      costs.append(head);
      for (const id of TECHNIQUES) {
        const cost = storageCost({ technique: id, precision, channels, size: naive.size });
        const row = el('tr', id === technique ? 'nm-current' : '');
        row.append(el('th', '', techniqueName(id)), el('td', '', fixed(cost.bytes / 1024, 1)), el('td', '', String(cost.components)),
          el('td', '', t(cost.varianceKept ? 'cost.yes' : 'cost.no')));
        costs.append(row);
      }
      return { meanLength };
    },
  };
}
