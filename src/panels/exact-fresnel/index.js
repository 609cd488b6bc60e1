// @ts-check
// Panel `exact-fresnel`: the lecture's exact formula typeset, then every quantity in it evaluated
// live (m, cos θ, c, g², g, both factors, R) and checked against fresnelExact and (Rs + Rp)/2.
// Past the critical angle g² < 0 and the code returns 1; a side box evaluates g² in the slide's
// order and in the code's order to show the cancellation the code avoids. No WebGL: KaTeX + uPlot.
import { DEG } from '../../optics/angles.js';
import { reflectanceCurves } from '../../optics/curves.js';
import { criticalAngle, fresnelExact, fresnelPolarized } from '../../optics/fresnel.js';
import { fresnelLiteral, fresnelTerms } from './physics.js';
import { createLinePlot } from '../../ui/createLinePlot.js';
import { el } from '../../ui/el.js';
import { angle, fixed as fixedTo, sci } from '../../ui/format.js';
import { definitionList } from '../../ui/definitionList.js';
import { criticalMark, thetaMark } from '../../ui/plotMarks.js';
import { texElement } from '../../ui/tex.js';
import { addSwap } from '../shared/indexPair.js';
import { addDielectricTrace } from '../shared/dielectricTrace.js';
import './styles.css';
import { schema } from './schema.js';
import { makeScrollBox, scrollBox } from '../../ui/scrollBox.js';
import { indexText } from '../shared/indexText.js';
import english from 'virtual:messages/en/exact-fresnel';
import sharedWords from 'virtual:messages/en/panelsShared';
import { messages } from '../../i18n/messages.js';

export { schema };

const t = messages('exact-fresnel', english);
const shared = messages('panelsShared', sharedWords);

// The slide's formula (lecture "Reflection Math"; Cook & Torrance 1982).
const FORMULA = String.raw`R(\theta) = \frac{1}{2}\left(\frac{g-c}{g+c}\right)^{2}`
  + String.raw`\left(1+\left(\frac{c(g+c)-m^{2}}{c(g-c)+m^{2}}\right)^{2}\right)`;
const DEFINITIONS = String.raw`c = m\cos\theta,\qquad g = \sqrt{1 + c^{2} - m^{2}},\qquad m = \frac{n_i}{n_t}`;

// One row per quantity: TeX, what it is (the catalogue's key, or none), and the word for a value that is not real.
const ROWS = [
  { key: 'm', tex: String.raw`m = n_i / n_t`, note: 'noteM' },
  { key: 'cos', tex: String.raw`\cos\theta`, note: '' },
  { key: 'c', tex: String.raw`c = m\cos\theta`, note: '' },
  { key: 'g2', tex: String.raw`g^{2} = (1-m)(1+m) + c^{2}`, note: 'noteG2' },
  { key: 'g', tex: String.raw`g = \sqrt{g^{2}}`, note: 'noteG', nan: 'imaginary' },
  { key: 'factor1', tex: String.raw`\left(\frac{g-c}{g+c}\right)^{2}`, note: 'noteFactor1' },
  { key: 'factor2', tex: String.raw`1+\left(\frac{c(g+c)-m^{2}}{c(g-c)+m^{2}}\right)^{2}`, note: 'noteFactor2' },
  { key: 'R', tex: String.raw`R = \tfrac{1}{2}\cdot\text{first}\cdot\text{second}`, note: 'noteR' },
];

/** Six decimals: the terms are shown to the float64 digits a reader can compare by eye. */
const fixed = (value, digits = 6) => fixedTo(value, digits);

function valueCell(key) {
  const cell = el('td', 'xf-value');
  cell.dataset.term = key;
  return cell;
}

/**
 * @param {HTMLElement} root
 * @param {import('../../host/panelContract.js').PanelContext<typeof schema>} ctx
 * @returns {import('../../host/panelContract.js').PanelInstance}
 */
export function mount(root, ctx) {
  const { values } = ctx;
  const panel = el('div', 'xf-panel');
  const formula = makeScrollBox(el('div', 'xf-formula'), t('formula'));
  formula.append(texElement(FORMULA), texElement(DEFINITIONS));

  const table = el('table', 'xf-terms');
  table.append(el('caption', 'xf-caption', t('caption')));
  const cells = {};
  const notes = {};
  for (const row of ROWS) {
    const tr = el('tr', row.key === 'R' ? 'xf-result' : '');
    const th = el('th', 'xf-symbol');
    th.scope = 'row';
    th.append(texElement(row.tex, { display: false, tag: 'span' }));
    cells[row.key] = valueCell(row.key);
    notes[row.key] = el('td', 'xf-note', row.note && t(row.note));
    tr.append(th, notes[row.key], cells[row.key]);
    table.append(tr);
  }

  const checks = definitionList('xf-checks', { valueClass: 'xf-value' });
  const check = (label, key) => checks.add(label, { check: key });
  const exactOut = check(t('checkExact'), 'exact');
  const polarOut = check(t('checkPolarized'), 'polarized');
  const diffOut = check(t('checkDifference'), 'difference');
  const status = el('p', 'xf-status');

  const why = el('section', 'xf-why');
  why.append(
    el('h3', '', t('whyHead')),
    el('p', '', t('why')),
  );
  const orders = el('table', 'xf-orders');
  const head = el('tr');
  head.append(el('th', '', t('ordersHead')), el('th', 'xf-num', 'g²'), el('th', 'xf-num', 'R'));
  const orderRow = (label, key) => {
    const tr = el('tr');
    tr.dataset.order = key;
    const g2 = el('td', 'xf-value');
    const r = el('td', 'xf-value');
    tr.append(el('th', '', label), g2, r);
    orders.append(tr);
    return { g2, r };
  };
  orders.append(head);
  const slideOrder = orderRow(t('orderSlide'), 'lecture');
  const codeOrder = orderRow(t('orderSafe'), 'safe');
  const cOut = el('p', 'xf-c');
  why.append(cOut, scrollBox(orders, t('orders')));

  const plotHost = el('div', 'xf-plot');
  plotHost.setAttribute('role', 'img');
  plotHost.setAttribute('aria-label', t('plot'));
  const left = el('div', 'xf-left');
  left.append(scrollBox(table, t('caption')), checks.element, status);
  const right = el('div', 'xf-right');
  right.append(why, plotHost);
  const body = el('div', 'xf-body');
  body.append(left, right);
  panel.append(formula, body);
  root.append(panel);

  const plot = createLinePlot(plotHost, {
    xLabel: t('xLabel'), yLabel: t('yLabel'), height: 240,
    series: [{ label: t('series'), stroke: '--c-exact', width: 3.5 }],
  });
  const trace = addDielectricTrace(plotHost, plot, () => values);

  const gui = ctx.gui;
  ctx.bind(gui, ['theta', 'nI', 'nT']);
  addSwap(ctx, gui, shared('swap'));
  ctx.tie(gui.add({ tir: () => ctx.set({ nI: 1.5, nT: 1, theta: 50 }) }, 'tir').name(t('tir')), ['nI', 'nT', 'theta']);
  ctx.tie(gui.add({ cancel: () => ctx.set({ nT: values.nI, theta: 90 }) }, 'cancel')
    .name(t('cancel')), ['nT', 'theta']);

  let curvesKey = '';
  let curves = null;
  let terms = null;
  let exact = 0;

  function update() {
    const { theta, nI, nT } = values;
    // Math.cos, not cosDeg: at 90° its 6e-17 is the tiny c that shows the slide's order failing.
    const cos = Math.cos(theta * DEG);
    terms = fresnelTerms(cos, nI, nT);
    exact = fresnelExact(cos, nI, nT);
    const { s, p } = fresnelPolarized(cos, nI, nT);

    for (const row of ROWS) {
      const v = terms[row.key];
      cells[row.key].textContent = Number.isNaN(v) ? (row.nan ? t(row.nan) : '—') : fixed(v);
    }
    cells.g2.classList.toggle('xf-negative', terms.g2 < 0);
    notes.R.textContent = terms.tir ? t('noteTir') : t('noteR');
    exactOut.textContent = fixed(exact);
    polarOut.textContent = t('polarizedValue', { mean: fixed(0.5 * (s + p)), s: fixed(s, 4), p: fixed(p, 4) });
    diffOut.textContent = sci(Math.abs(terms.R - exact), 1);

    panel.classList.toggle('xf-tir', terms.tir);
    if (terms.tir) {
      status.textContent = terms.g2 < 0 ? t('statusNegative', { g2: fixed(terms.g2) }) : t('statusCritical');
    } else if (terms.matched) {
      status.textContent = t('statusMatched');
    } else {
      status.textContent = t('statusReal', { g2: fixed(terms.g2), R: fixed(terms.R) });
    }

    const slide = fresnelLiteral(cos, nI, nT, 'lecture');
    const code = fresnelLiteral(cos, nI, nT, 'safe');
    cOut.textContent = t('now', { m: fixed(terms.m), c: sci(terms.c) });
    slideOrder.g2.textContent = sci(slide.g2);
    slideOrder.r.textContent = fixed(slide.R);
    codeOrder.g2.textContent = sci(code.g2);
    codeOrder.r.textContent = fixed(code.R);
    slideOrder.r.classList.toggle('xf-wrong', Math.abs(slide.R - exact) > 1e-6);

    const key = `${nI}|${nT}`;
    if (key !== curvesKey) {
      curvesKey = key;
      curves = reflectanceCurves(nI, nT);
      plot.setData([curves.theta, curves.exact]);
      trace.refresh();
    }
    const critical = criticalAngle(nI, nT);
    plot.setMarks([
      criticalMark(critical === null ? null : critical / DEG),
      thetaMark(theta, t('thetaMark', { theta: angle(theta), R: fixed(exact, 4) })),
    ]);
  }
  update();

  return {
    plot,
    update,
    get terms() { return terms; },
    describe() {
      const { theta, nI, nT } = values;
      const at = {
        theta: angle(theta), nI: indexText(nI), nT: indexText(nT), m: fixed(terms.m, 4), c: fixed(terms.c, 4), g2: fixed(terms.g2, 4),
      };
      if (terms.tir) return t('describeTir', at);
      return t('describe', {
        ...at, g: fixed(terms.g, 4), factor1: fixed(terms.factor1, 4), factor2: fixed(terms.factor2, 4), R: fixed(terms.R, 4),
      });
    },
    csv() {
      const { s, p } = curves;
      return {
        filename: `exact-fresnel-nI${values.nI}-nT${values.nT}.csv`,
        columns: { theta_deg: curves.theta, R_exact: curves.exact, Rs: s, Rp: p },
      };
    },
    png: () => plot.toPng(),
    trace,
    dispose() {
      trace.dispose();
      plot.dispose();
      panel.remove();
    },
  };
}
