// @ts-check
// Panel `schlick`: Schlick's approximation typeset with the live R0 put in, exact against
// Schlick (and Schlick on cos θt from the denser side) over θ with the error curves, the largest
// error of each found by sampling, and a readout at a chosen θ. No WebGL: KaTeX + uPlot.
import { cosDeg, DEG } from '../../optics/angles.js';
import {
  fresnelExact, fresnelSchlick, fresnelSchlickTIR, normalIncidence, snellCosT,
} from '../../optics/fresnel.js';
import { schlickComparison } from './physics.js';
import { createLinePlot } from '../../ui/createLinePlot.js';
import { el } from '../../ui/el.js';
import { angle as deg, fixed as fixedTo } from '../../ui/format.js';
import { criticalMark, thetaMark } from '../../ui/plotMarks.js';
import { renderTex, texElement, texNumber } from '../../ui/tex.js';
import { definitionList } from '../../ui/definitionList.js';
import { addSwap } from '../shared/indexPair.js';
import { addDielectricTrace } from '../shared/dielectricTrace.js';
import './styles.css';
import { schema } from './schema.js';
import { makeScrollBox } from '../../ui/scrollBox.js';
import { indexText } from '../shared/indexText.js';
import english from 'virtual:messages/en/schlick';
import sharedWords from 'virtual:messages/en/panelsShared';
import { messages } from '../../i18n/messages.js';

export { schema };

const t = messages('schlick', english);
const shared = messages('panelsShared', sharedWords);

// Schlick, "An Inexpensive BRDF Model for Physically-based Rendering", CGF 13(3), 1994; lecture slide.
const FORMULA = String.raw`R(\theta) \approx R_{\mathrm{S}}(\theta) = R_0 + (1 - R_0)(1 - \cos\theta)^{5}`;
/** The curves, named in the page's language. */
const series = () => [
  { label: t('exact'), stroke: '--c-exact', width: 3.5 },
  { label: t('seriesSchlick'), stroke: '--c-schlick', width: 3.5, dash: [12, 6] },
  { label: t('seriesSchlickT'), stroke: '--c-p', width: 3, dash: [4, 4] },
  { label: t('seriesError'), stroke: '--c-error', width: 2.5 },
  { label: t('errorT'), stroke: '--c-s', width: 3, dash: [6, 4] },
];

const fixed = (value, digits = 6) => fixedTo(value, digits);

/**
 * @param {HTMLElement} root
 * @param {import('../../host/panelContract.js').PanelContext<typeof schema>} ctx
 * @returns {import('../../host/panelContract.js').PanelInstance}
 */
export function mount(root, ctx) {
  const { values } = ctx;
  const panel = el('div', 'sk-panel');
  const formulas = makeScrollBox(el('div', 'sk-formulas'), t('formulas'));
  const r0Tex = el('div', 'sk-tex');
  const atTex = el('div', 'sk-tex');
  formulas.append(texElement(FORMULA), r0Tex, atTex);

  const readout = definitionList('sk-readout', { valueClass: 'sk-value' });
  const item = (key) => readout.add(t(key), { out: key });
  const out = {
    exact: item('exact'), schlick: item('schlick'), error: item('error'), schlickT: item('schlickT'), errorT: item('errorT'),
  };
  const tirNote = el('p', 'sk-note');

  const summary = definitionList('sk-summary', { valueClass: 'sk-value' });
  const worstOut = summary.add(t('worst'), { worst: 'schlick' });
  const worstTOut = summary.add(t('worstT'), { worst: 'cosThetaT' });

  const plotHost = el('div', 'sk-plot');
  plotHost.setAttribute('role', 'img');
  plotHost.setAttribute('aria-label', t('plot'));
  panel.append(formulas, readout.element, tirNote, summary.element, plotHost);
  root.append(panel);

  const plot = createLinePlot(plotHost, {
    xLabel: t('xLabel'), yLabel: t('yLabel'), series: series(), height: 340,
  });
  const trace = addDielectricTrace(plotHost, plot, () => values, ['exact', 'schlick', 'schlickT']);

  ctx.bind(ctx.gui, ['nI', 'nT', 'theta']);
  addSwap(ctx, ctx.gui, shared('swapLookOut'));

  let key = '';
  let cmp = null;

  function refreshCurves() {
    const { nI, nT } = values;
    cmp = schlickComparison(nI, nT);
    const inside = nI > nT;
    const none = cmp.theta.map(() => null); // Schlick on cos θt is Schlick itself when nI ≤ nT
    plot.setData([cmp.theta, cmp.exact, cmp.schlick, inside ? cmp.schlickT : none, cmp.error, inside ? cmp.errorT : none]);
    trace.refresh();
    worstOut.textContent = t('valueAt', { value: fixed(cmp.worst.value, 4), angle: deg(cmp.worst.theta) });
    worstTOut.textContent = inside
      ? t('valueAt', { value: fixed(cmp.worstT.value, 4), angle: deg(cmp.worstT.theta) })
      : t('sameAsSchlick');
    const r0 = normalIncidence(nI, nT);
    renderTex(r0Tex, String.raw`R_0 = \left(\frac{n_t - n_i}{n_t + n_i}\right)^{2}
      = \left(\frac{${texNumber(nT)} - ${texNumber(nI)}}{${texNumber(nT)} + ${texNumber(nI)}}\right)^{2} = ${fixed(r0)}`);
  }

  function update() {
    const { nI, nT, theta } = values;
    if (`${nI}|${nT}` !== key) {
      key = `${nI}|${nT}`;
      refreshCurves();
    }
    const cos = cosDeg(theta);
    const r0 = normalIncidence(nI, nT);
    const exact = fresnelExact(cos, nI, nT);
    const schlick = fresnelSchlick(cos, nI, nT);
    const schlickT = fresnelSchlickTIR(cos, nI, nT);
    renderTex(atTex, String.raw`R_{\mathrm{S}}(${texNumber(theta, 2)}^\circ) = ${fixed(r0)} + ${fixed(1 - r0)}\,
      (1 - ${fixed(cos)})^{5} = ${fixed(schlick)}`);
    out.exact.textContent = fixed(exact);
    out.schlick.textContent = fixed(schlick);
    out.error.textContent = fixed(Math.abs(exact - schlick));
    out.schlickT.textContent = fixed(schlickT);
    out.errorT.textContent = fixed(Math.abs(exact - schlickT));

    const cosT = snellCosT(cos, nI, nT);
    if (nI <= nT) {
      tirNote.textContent = t('noteOutside');
    } else if (cosT === null) {
      tirNote.textContent = t('noteTir', { critical: deg(cmp.critical) });
    } else {
      tirNote.textContent = t('noteInside', { cosT: fixed(cosT), thetaT: deg(Math.acos(cosT) / DEG), critical: deg(cmp.critical) });
    }
    panel.classList.toggle('sk-inside', nI > nT);

    plot.setMarks([
      criticalMark(cmp.critical),
      { x: cmp.worst.theta, color: '--c-error', label: t('maxMark', { value: fixed(cmp.worst.value, 3) }) },
      thetaMark(theta),
    ]);
  }
  update();

  return {
    plot,
    update,
    get comparison() { return cmp; },
    describe() {
      const { nI, nT, theta } = values;
      const cos = cosDeg(theta);
      return t('describe', {
        nI: indexText(nI), nT: indexText(nT), r0: fixed(normalIncidence(nI, nT), 4), theta: deg(theta),
        exact: fixed(fresnelExact(cos, nI, nT), 4), schlick: fixed(fresnelSchlick(cos, nI, nT), 4),
        worst: fixed(cmp.worst.value, 4), worstAngle: deg(cmp.worst.theta),
        inside: nI > nT ? 'yes' : 'no', worstT: fixed(cmp.worstT.value, 4), worstTAngle: deg(cmp.worstT.theta),
      });
    },
    csv() {
      return {
        filename: `schlick-nI${values.nI}-nT${values.nT}.csv`,
        columns: {
          theta_deg: cmp.theta, R_exact: cmp.exact, R_schlick: cmp.schlick, R_schlick_cos_theta_t: cmp.schlickT,
          abs_error_schlick: cmp.error, abs_error_schlick_cos_theta_t: cmp.errorT,
        },
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
