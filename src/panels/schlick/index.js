// @ts-check
// Panel `schlick`: Schlick's approximation typeset with the live R0 put in, exact against
// Schlick (and Schlick on cos θt from the denser side) over θ with the error curves, the largest
// error of each found by sampling, and a readout at a chosen θ. No WebGL: KaTeX + uPlot.
import { cosDeg, DEG } from '../../optics/angles.js';
import {
  fresnelExact, fresnelSchlick, fresnelSchlickTIR, normalIncidence, snellCosT,
} from '../../optics/fresnel.js';
import { schlickComparison } from './schlickComparison.js';
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

export { schema };

// Schlick, "An Inexpensive BRDF Model for Physically-based Rendering", CGF 13(3), 1994; lecture slide.
const FORMULA = String.raw`R(\theta) \approx R_{\mathrm{S}}(\theta) = R_0 + (1 - R_0)(1 - \cos\theta)^{5}`;
const SERIES = [
  { label: 'Exact', stroke: '--c-exact', width: 3.5 },
  { label: 'Schlick (cos θ)', stroke: '--c-schlick', width: 3.5, dash: [12, 6] },
  { label: 'Schlick (cos θt)', stroke: '--c-p', width: 3, dash: [4, 4] },
  { label: '|error| Schlick', stroke: '--c-error', width: 2.5 },
  { label: '|error| on cos θt', stroke: '--c-s', width: 3, dash: [6, 4] },
];

const fixed = (value, digits = 6) => fixedTo(value, digits);

/**
 * @param {HTMLElement} root
 * @param {import('../../host/panelContract.js').PanelContext} ctx
 * @returns {import('../../host/panelContract.js').PanelInstance}
 */
export function mount(root, ctx) {
  const { values } = ctx;
  const panel = el('div', 'sk-panel');
  const formulas = makeScrollBox(el('div', 'sk-formulas'), 'Schlick’s approximation and its terms');
  const r0Tex = el('div', 'sk-tex');
  const atTex = el('div', 'sk-tex');
  formulas.append(texElement(FORMULA), r0Tex, atTex);

  const readout = definitionList('sk-readout', { valueClass: 'sk-value' });
  const item = (label, key) => readout.add(label, { out: key });
  const out = {
    exact: item('Exact', 'exact'), schlick: item('Schlick', 'schlick'), error: item('|error|', 'error'),
    schlickT: item('Schlick on cos θt', 'schlickT'), errorT: item('|error| on cos θt', 'errorT'),
  };
  const tirNote = el('p', 'sk-note');

  const summary = definitionList('sk-summary', { valueClass: 'sk-value' });
  const worstOut = summary.add('Largest |exact − Schlick|', { worst: 'schlick' });
  const worstTOut = summary.add('Largest |exact − Schlick on cos θt|', { worst: 'cosThetaT' });

  const plotHost = el('div', 'sk-plot');
  plotHost.setAttribute('role', 'img');
  plotHost.setAttribute('aria-label', 'Exact reflectance, Schlick on cos θ, Schlick on cos θt and their errors against θ');
  panel.append(formulas, readout.element, tirNote, summary.element, plotHost);
  root.append(panel);

  const plot = createLinePlot(plotHost, {
    xLabel: 'θ, angle from the normal (degrees)', yLabel: 'Reflectance R and |error|', series: SERIES, height: 340,
  });
  const trace = addDielectricTrace(plotHost, plot, () => values, ['exact', 'schlick', 'schlickT']);

  ctx.bind(ctx.gui, ['nI', 'nT', 'theta']);
  addSwap(ctx, ctx.gui, 'Swap n_i ↔ n_t (look out of the glass)');

  let key = '';
  let cmp = null;

  function refreshCurves() {
    const { nI, nT } = values;
    cmp = schlickComparison(nI, nT);
    const inside = nI > nT;
    const none = cmp.theta.map(() => null); // Schlick on cos θt is Schlick itself when nI ≤ nT
    plot.setData([cmp.theta, cmp.exact, cmp.schlick, inside ? cmp.schlickT : none, cmp.error, inside ? cmp.errorT : none]);
    trace.refresh();
    worstOut.textContent = `${fixed(cmp.worst.value, 4)} at ${deg(cmp.worst.theta)}`;
    worstTOut.textContent = inside
      ? `${fixed(cmp.worstT.value, 4)} at ${deg(cmp.worstT.theta)}`
      : 'same as Schlick (n_i ≤ n_t)';
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
      tirNote.textContent = 'From the less dense side θt < θ, so Schlick on cos θ is the textbook choice.';
    } else if (cosT === null) {
      tirNote.textContent = `Past the critical angle ${deg(cmp.critical)}: total internal reflection, exact R = 1. `
        + 'Schlick on cos θ has no idea; Schlick on cos θt returns 1.';
    } else {
      tirNote.textContent = `From the denser side: cos θt = ${fixed(cosT)} (θt = ${deg(Math.acos(cosT) / DEG)}); `
        + `Schlick must use the larger angle. Critical angle ${deg(cmp.critical)}.`;
    }
    panel.classList.toggle('sk-inside', nI > nT);

    plot.setMarks([
      criticalMark(cmp.critical),
      { x: cmp.worst.theta, color: '--c-error', label: `Max |error| ${fixed(cmp.worst.value, 3)}` },
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
      const inside = nI > nT
        ? ` Schlick on cos θt is off by at most ${fixed(cmp.worstT.value, 4)} at ${deg(cmp.worstT.theta)}.`
        : '';
      return `From n_i = ${nI} into n_t = ${nT}, R0 = ${fixed(normalIncidence(nI, nT), 4)}. At θ = ${deg(theta)} `
        + `exact R is ${fixed(fresnelExact(cos, nI, nT), 4)} and Schlick gives ${fixed(fresnelSchlick(cos, nI, nT), 4)}. `
        + `Schlick's largest error is ${fixed(cmp.worst.value, 4)} at ${deg(cmp.worst.theta)}.${inside}`;
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
