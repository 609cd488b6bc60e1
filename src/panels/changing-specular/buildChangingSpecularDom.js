// The DOM of the changing-specular panel: the two rendered floors with their labels, a cross-section
// (SVG) of light, normal, mirror direction r, view v and Phong's lobe, the live formulas, and the
// plot host. Styled by styles.css under .cspec-panel.
import english from 'virtual:messages/en/changing-specular';
import { messages } from '../../i18n/messages.js';
import { renderTex, texNumber } from '../../ui/tex.js';
import { fixed, markupNumber as num, tickLabel } from '../../ui/format.js';
import './styles.css';
import { el } from '../../ui/el.js';
import { DEG } from '../../optics/angles.js';
import { schema } from './schema.js';

const t = messages('changing-specular', english);
const SVG = 'http://www.w3.org/2000/svg';

function svg(tag, attrs = {}, parent = null) {
  const node = document.createElementNS(SVG, tag);
  for (const [k, v] of Object.entries(attrs)) node.setAttribute(k, v);
  parent?.append(node);
  return node;
}

// Cross-section geometry: the hit point O, ray length, SVG y pointing down.
const O = [210, 200];
const LEN = 150;
const at = (psiDeg, len = LEN) => [O[0] + len * Math.cos(psiDeg * DEG), O[1] - len * Math.sin(psiDeg * DEG)];

function buildDiagram() {
  const root = svg('svg', { viewBox: '0 0 420 230', class: 'cspec-diagram', role: 'img' });
  // One arrowhead per colour (a marker does not take its colour from the line that uses it).
  svg('defs', {}, root).innerHTML = ['light', 'mirror', 'view', 'normal'].map((k) => `<marker id="cspec-mk-${k}" `
    + `class="cspec-mk-${k}" viewBox="0 0 10 10" refX="9" refY="5" markerWidth="6" markerHeight="6" orient="auto">`
    + '<path d="M0 0L10 5L0 10z"/></marker>').join('');
  svg('line', { x1: 15, y1: O[1], x2: 405, y2: O[1], class: 'cspec-surface' }, root);
  const lobe = svg('path', { class: 'cspec-lobe' }, root);
  svg('line', { x1: O[0], y1: O[1], x2: O[0], y2: O[1] - 120, class: 'cspec-normal', 'marker-end': 'url(#cspec-mk-normal)' }, root);
  const arc = svg('path', { class: 'cspec-arc' }, root);
  const light = svg('line', { class: 'cspec-light', 'marker-end': 'url(#cspec-mk-light)' }, root);
  const mirror = svg('line', { class: 'cspec-mirror', 'marker-end': 'url(#cspec-mk-mirror)' }, root);
  const view = svg('line', { class: 'cspec-view', 'marker-end': 'url(#cspec-mk-view)' }, root);
  const sun = svg('circle', { r: 11, class: 'cspec-sun' }, root);
  const eye = svg('circle', { r: 9, class: 'cspec-eye' }, root);
  const label = (cls, text) => {
    const node = svg('text', { class: cls }, root);
    node.textContent = text;
    return node;
  };
  const nLabel = label('cspec-label', 'n');
  nLabel.setAttribute('x', O[0] + 18);
  nLabel.setAttribute('y', O[1] - 108);
  const labels = { l: label('cspec-label cspec-l', t('diagramLight')), r: label('cspec-label cspec-r', 'r'),
    v: label('cspec-label cspec-v', 'v'), theta: label('cspec-label', 'θ') };

  const place = (node, [x, y]) => { node.setAttribute('x', num(x, 1)); node.setAttribute('y', num(y, 1)); };
  const line = (node, from, to) => {
    node.setAttribute('x1', num(from[0], 1)); node.setAttribute('y1', num(from[1], 1));
    node.setAttribute('x2', num(to[0], 1)); node.setAttribute('y2', num(to[1], 1));
  };

  /** Light on the right at lightEl, mirror direction and viewer on the left; lobe (v·r)^s around r. */
  function update(lightEl, viewEl, s) {
    const psiL = lightEl;
    const psiR = 180 - lightEl;
    const psiV = 180 - viewEl;
    const sunAt = at(psiL, LEN + 14);
    sun.setAttribute('cx', sunAt[0]); sun.setAttribute('cy', sunAt[1]);
    line(light, at(psiL), at(psiL, 4));
    line(mirror, O, at(psiR, LEN - 25));
    line(view, O, at(psiV, LEN - 2));
    const eyeAt = at(psiV, LEN + 10);
    eye.setAttribute('cx', eyeAt[0]); eye.setAttribute('cy', eyeAt[1]);
    // Labels: above the sun and the eye, and r beside the middle of its arrow (clear of v when they
    // coincide, which they do at the mirror peak).
    place(labels.l, [sunAt[0], sunAt[1] - 18]);
    place(labels.v, [eyeAt[0], eyeAt[1] - 16]);
    const mid = at(psiR, 80);
    const side = psiR + (lightEl > 45 ? 90 : -90); // away from the normal when r is steep, else above r
    place(labels.r, [mid[0] + 18 * Math.cos(side * DEG), mid[1] - 18 * Math.sin(side * DEG) + 6]);
    // Phong's lobe (v·r)^s, radius 120 at its peak: its shape alone, the same in both models.
    const points = [];
    for (let psi = 0; psi <= 180; psi += 1) {
      const c = Math.cos((psi - psiR) * DEG);
      points.push(at(psi, 120 * (c > 0 ? c ** s : 0)));
    }
    lobe.setAttribute('d', `M${O[0]} ${O[1]}${points.map(([x, y]) => `L${num(x, 1)} ${num(y, 1)}`).join('')}Z`);
    // θ between the normal and the light.
    const a = at(90, 46);
    const b = at(psiL, 46);
    arc.setAttribute('d', `M${num(a[0], 1)} ${num(a[1], 1)}A46 46 0 0 1 ${num(b[0], 1)} ${num(b[1], 1)}`);
    place(labels.theta, at((90 + psiL) / 2, 60));
    const deg = (x) => tickLabel(x, schema.lightEl.step);
    root.setAttribute('aria-label', t('diagramLabel', { light: deg(lightEl), theta: deg(90 - lightEl), view: deg(viewEl) }));
  }
  return { root, update };
}

export function buildChangingSpecularDom(host) {
  const root = el('div', 'cspec-panel');
  const stage = el('div', 'cspec-stage');
  const canvas = el('canvas', 'cspec-canvas');
  canvas.setAttribute('role', 'img');
  canvas.setAttribute('aria-label', t('canvasLabel'));
  const labels = el('div', 'cspec-labels');
  const left = el('span', 'cspec-tag cspec-tag-phong', t('tagPhong'));
  const right = el('span', 'cspec-tag cspec-tag-fresnel', t('tagFresnel'));
  labels.append(left, right);
  stage.append(canvas, labels);

  const row = el('div', 'cspec-row');
  const diagram = buildDiagram();
  const maths = el('div', 'cspec-maths');
  const texPhong = el('div', 'cspec-tex cspec-tex-phong');
  const texFresnel = el('div', 'cspec-tex cspec-tex-fresnel');
  const note = el('p', 'cspec-note');
  maths.append(texPhong, texFresnel, note);
  row.append(diagram.root, maths);
  const plot = el('div', 'cspec-plot');
  plot.setAttribute('aria-label', t('plotLabel'));
  root.append(stage, row, plot);
  host.append(root);

  return {
    stage,
    canvas,
    plot,
    setDiagram: diagram.update,
    /** Live formulas at the centre of view. */
    setNumbers(h, s) {
      const lobe = `(${texNumber(h.vDotR, 3)})^{${s}}`;
      // Inline style, so a narrow panel wraps the line at = and × instead of cutting it off.
      renderTex(texPhong, `\\text{Phong} = R_0\\,(\\mathbf v\\cdot\\mathbf r)^s = ${texNumber(h.R0)} \\times ${lobe} `
        + `= \\mathbf{${texNumber(h.phong)}}`, { display: false });
      renderTex(texFresnel, `\\text{Phong}\\times F = F(${texNumber(h.thetaDeg, 1)}^\\circ)\\,(\\mathbf v\\cdot\\mathbf r)^s = `
        + `${texNumber(h.F)} \\times ${lobe} = \\mathbf{${texNumber(h.phongF)}}`, { display: false });
      const ratio = fixed(h.F / h.R0, 2);
      note.textContent = h.R0 === 0 ? t('noteNoInterface') : t('note', { ratio });
    },
  };
}
