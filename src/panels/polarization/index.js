// @ts-check
// Panel `polarization`: Rs, Rp and their mean (the exact unpolarized R) against θ, with Brewster's
// angle (Rp = 0) and the critical angle marked, a readout at a chosen θ, and why a tool that shows
// only Rs reads high at oblique angles. Curves from curves.js; point values from fresnel.js.
import { brewsterAngle, criticalAngle, fresnelExact, fresnelPolarized } from '../../optics/fresnel.js';
import { cosDeg, DEG } from '../../optics/angles.js';
import { reflectanceCurves } from '../../optics/curves.js';
import { createLinePlot } from '../../ui/createLinePlot.js';
import { el } from '../../ui/el.js';
import { definitionList } from '../../ui/definitionList.js';
import { angle, fixed } from '../../ui/format.js';
import { brewsterMark, criticalMark, thetaMark } from '../../ui/plotMarks.js';
import { addSwap } from '../shared/indexPair.js';
import './styles.css';
import { schema } from './schema.js';
import { addDielectricTrace } from '../shared/dielectricTrace.js';
import sharedWords from 'virtual:messages/en/panelsShared';
import { messages } from '../../i18n/messages.js';

export { schema };

const shared = messages('panelsShared', sharedWords);

const SERIES = [
  { label: 'Rs (s-polarized)', stroke: '--c-s', width: 3 },
  { label: 'Rp (p-polarized)', stroke: '--c-p', width: 3 },
  { label: 'Mean = exact unpolarized R', stroke: '--c-exact', width: 3.5, dash: [10, 6] },
];

/** Values at one angle: Rs, Rp (fresnelPolarized) and the unpolarized mean (fresnelExact). */
function at(thetaDeg, nI, nT) {
  const c = cosDeg(thetaDeg);
  const { s, p } = fresnelPolarized(c, nI, nT);
  return { s, p, mean: fresnelExact(c, nI, nT) };
}

/**
 * @param {HTMLElement} root
 * @param {import('../../host/panelContract.js').PanelContext} ctx
 * @returns {import('../../host/panelContract.js').PanelInstance}
 */
export function mount(root, ctx) {
  const { values } = ctx;
  const panel = el('div', 'polarization-panel');
  const summary = definitionList('pol-summary');
  const items = {
    brewster: summary.add('Brewster angle'),
    atBrewster: summary.add('At Brewster'),
    critical: summary.add('Critical angle'),
  };
  const plotHost = el('div', 'pol-plot');
  plotHost.setAttribute('role', 'img');
  plotHost.setAttribute('aria-label', 'Rs, Rp and their mean against the angle of incidence θ');
  const readout = el('p', 'pol-readout');
  readout.setAttribute('aria-live', 'polite');
  // Why an Rs-only reading is high: Rs ≥ Rp at every angle for a dielectric (|rp| = |rs|·
  // |cos(θ_i + θ_t)/cos(θ_i − θ_t)|, Hecht §4.6.2), so Rs is at least their mean; equal only head-on,
  // at grazing incidence and under total internal reflection.
  const note = el('p', 'pol-note',
    'Some simulations and meters report only Rs, the reflectance for light polarized across the plane of '
    + 'incidence. Sunlight and lamps are unpolarized: half their light is s and half is p, so what reflects is '
    + 'the average of Rs and Rp. Rp is never larger than Rs and drops to zero at Brewster\'s angle, so an '
    + 'Rs-only number reads too high at oblique angles. ');
  const noteNumbers = el('strong', 'pol-note-numbers');
  note.append(noteNumbers);
  panel.append(summary.element, plotHost, readout, note);
  root.append(panel);

  const plot = createLinePlot(plotHost, {
    xLabel: 'θ, angle of incidence', yLabel: 'Reflectance',
    series: SERIES,
    height: 340,
  });
  // Rp first: its fall to zero is the Brewster angle, heard as the pitch reaching the bottom.
  const trace = addDielectricTrace(plotHost, plot, () => values, ['p', 's', 'exact']);

  const folder = ctx.gui.addFolder('Interface and readout');
  ctx.bind(folder, ['nI', 'nT', 'theta']);
  ctx.tie(folder.add({ go: () => ctx.set({ theta: Math.round((brewsterAngle(values.nI, values.nT) / DEG) * 100) / 100 }) }, 'go')
    .name('Read at the Brewster angle'), ['theta']);
  addSwap(ctx, folder, shared('swap'));

  let curves = null;
  let curvesKey = '';
  let point = null;
  let brewster = 0;
  let critical = null;

  function update() {
    const { nI, nT, theta } = values;
    const key = `${nI}|${nT}`;
    if (key !== curvesKey) {
      curvesKey = key;
      curves = reflectanceCurves(nI, nT);
      plot.setData([curves.theta, curves.s, curves.p, curves.exact]);
      trace.refresh();
      brewster = brewsterAngle(nI, nT) / DEG;
      const c = criticalAngle(nI, nT);
      critical = c === null ? null : c / DEG;
      const b = at(brewster, nI, nT);
      items.brewster.textContent = angle(brewster);
      items.atBrewster.textContent = `Rp = ${fixed(b.p, 4)}, Rs = ${fixed(b.s, 4)}`;
      items.critical.textContent = critical === null ? 'none (n_i ≤ n_t)' : angle(critical);
    }
    plot.setMarks([brewsterMark(brewster, ' (Rp = 0)'), criticalMark(critical), thetaMark(theta, `θ = ${angle(theta)}`)]);
    point = at(theta, nI, nT);
    readout.textContent = `At θ = ${angle(theta)}   Rs = ${fixed(point.s, 4)}   Rp = ${fixed(point.p, 4)}   `
      + `unpolarized mean = ${fixed(point.mean, 4)}`;
    noteNumbers.textContent = explain(point, theta, nI, nT);
  }

  /** The sentence with this angle's numbers. */
  function explain({ s, p, mean }, theta, nI, nT) {
    if (nI === nT) return 'Here n_i = n_t: there is no interface and nothing reflects.';
    if (s - mean < 5e-5) {
      return `At ${angle(theta)} the two agree (Rs = ${fixed(s, 4)}, mean = ${fixed(mean, 4)}): `
        + (p > 0.9999 ? 'everything is reflected.' : 's and p reflect alike there.');
    }
    return `At ${angle(theta)}: Rs = ${fixed(s, 4)} against the unpolarized ${fixed(mean, 4)}, `
      + `${fixed(s / mean, 2)} times too high (Rp = ${fixed(p, 4)}).`;
  }
  update();

  return {
    plot,
    get point() { return point; },
    update,
    describe() {
      const { nI, nT, theta } = values;
      return `From n_i = ${nI} into n_t = ${nT}: at ${angle(theta)} Rs = ${fixed(point.s, 4)}, `
        + `Rp = ${fixed(point.p, 4)} and their mean, the unpolarized R, is ${fixed(point.mean, 4)}; `
        + `Rp is 0 at the Brewster angle ${angle(brewster)}`
        + (critical === null ? '.' : `; past the critical angle ${angle(critical)} both are 1.`);
    },
    csv() {
      return {
        filename: `polarization-nI${values.nI}-nT${values.nT}.csv`,
        columns: { theta_deg: curves.theta, Rs: curves.s, Rp: curves.p, R_unpolarized: curves.exact },
      };
    },
    /** The plot on the panel's background (uPlot's canvas is transparent). */
    png: () => plot.toPng(),
    trace,
    dispose() {
      trace.dispose();
      plot.dispose();
      panel.remove();
    },
  };
}
