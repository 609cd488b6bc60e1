// Panel `polarization`: Rs, Rp and their mean (the exact unpolarized R) against θ, with Brewster's
// angle (Rp = 0) and the critical angle marked, a readout at a chosen θ, and why a tool that shows
// only Rs reads high at oblique angles. Curves from curves.js; point values from fresnel.js.
import { brewsterAngle, criticalAngle, fresnelExact, fresnelPolarized } from '../optics/fresnel.js';
import { reflectanceCurves } from '../optics/curves.js';
import { cosDeg } from '../optics/interfaceSplit.js';
import { createLinePlot } from '../ui/createLinePlot.js';
import './polarization.css';
import { el } from '../ui/el.js';

export const id = 'polarization';
export const title = 'Why the exact formula is an average: polarization';
export const usesWebGL = false;
export const materialParam = 'n2';

export const schema = {
  n1: { type: 'number', default: 1, min: 1, max: 3, step: 0.0001, label: 'n₁ (incident side)' },
  n2: { type: 'number', default: 1.5, min: 1, max: 3, step: 0.0001, label: 'n₂ (other side)' },
  theta: { type: 'number', default: 60, min: 0, max: 90, step: 0.01, label: 'Readout angle θ (°)' },
};

const DEG = Math.PI / 180;
const SERIES = [
  { label: 'Rs (s-polarized)', stroke: '--c-s', width: 3 },
  { label: 'Rp (p-polarized)', stroke: '--c-p', width: 3 },
  { label: 'Mean = exact unpolarized R', stroke: '--c-exact', width: 3.5, dash: [10, 6] },
];

/** Values at one angle: Rs, Rp (fresnelPolarized) and the unpolarized mean (fresnelExact). */
function at(thetaDeg, n1, n2) {
  const c = cosDeg(thetaDeg);
  const { s, p } = fresnelPolarized(c, n1, n2);
  return { s, p, mean: fresnelExact(c, n1, n2) };
}

function summaryItem(term) {
  const wrap = el('div');
  const dd = el('dd');
  wrap.append(el('dt', '', term), dd);
  return { wrap, dd };
}

export function mount(root, ctx) {
  const { values } = ctx;
  const panel = el('div', 'polarization-panel');
  const summary = el('dl', 'pol-summary');
  const items = {
    brewster: summaryItem('Brewster angle'),
    atBrewster: summaryItem('At Brewster'),
    critical: summaryItem('Critical angle'),
  };
  summary.append(...Object.values(items).map((i) => i.wrap));
  const plotHost = el('div', 'pol-plot');
  plotHost.setAttribute('role', 'img');
  plotHost.setAttribute('aria-label', 'Rs, Rp and their mean against the angle of incidence θ');
  const readout = el('p', 'pol-readout');
  readout.setAttribute('aria-live', 'polite');
  // Why an Rs-only reading is high: Rs ≥ Rp at every angle for a dielectric (|rp| = |rs|·
  // |cos(θ₁ + θ₂)/cos(θ₁ − θ₂)|, Hecht §4.6.2), so Rs is at least their mean; equal only head-on,
  // at grazing incidence and under total internal reflection.
  const note = el('p', 'pol-note',
    'Some simulations and meters report only Rs, the reflectance for light polarized across the plane of '
    + 'incidence. Sunlight and lamps are unpolarized: half their light is s and half is p, so what reflects is '
    + 'the average of Rs and Rp. Rp is never larger than Rs and drops to zero at Brewster\'s angle, so an '
    + 'Rs-only number reads too high at oblique angles. ');
  const noteNumbers = el('strong', 'pol-note-numbers');
  note.append(noteNumbers);
  panel.append(summary, plotHost, readout, note);
  root.append(panel);

  const plot = createLinePlot(plotHost, {
    xLabel: 'θ, angle of incidence', yLabel: 'Reflectance',
    series: SERIES,
    height: 340,
  });

  const folder = ctx.gui.addFolder('Interface and readout');
  ctx.bind(folder, ['n1', 'n2', 'theta']);
  const set = (update) => { Object.assign(values, update); ctx.changed(Object.keys(update)); };
  folder.add({ go: () => set({ theta: Math.round((brewsterAngle(values.n1, values.n2) / DEG) * 100) / 100 }) }, 'go')
    .name('Read at the Brewster angle');
  folder.add({ swap: () => set({ n1: values.n2, n2: values.n1 }) }, 'swap').name('Swap n₁ ↔ n₂');

  let curves = null;
  let curvesKey = '';
  let point = null;
  let brewster = 0;
  let critical = null;

  function update() {
    const { n1, n2, theta } = values;
    const key = `${n1}|${n2}`;
    if (key !== curvesKey) {
      curvesKey = key;
      curves = reflectanceCurves(n1, n2);
      plot.setData([curves.theta, curves.s, curves.p, curves.exact]);
      brewster = brewsterAngle(n1, n2) / DEG;
      const c = criticalAngle(n1, n2);
      critical = c === null ? null : c / DEG;
      const b = at(brewster, n1, n2);
      items.brewster.dd.textContent = `${brewster.toFixed(2)}°`;
      items.atBrewster.dd.textContent = `Rp = ${b.p.toFixed(4)}, Rs = ${b.s.toFixed(4)}`;
      items.critical.dd.textContent = critical === null ? 'none (n₁ ≤ n₂)' : `${critical.toFixed(2)}°`;
    }
    plot.setMarks([
      { x: brewster, color: '--c-brewster', label: `Brewster ${brewster.toFixed(2)}° (Rp = 0)` },
      critical === null ? null
        : { x: critical, color: '--c-critical', label: `critical ${critical.toFixed(2)}°`, shadeTo: 90 },
      { x: theta, color: '--c-marker', label: `θ = ${theta.toFixed(2)}°` },
    ]);
    point = at(theta, n1, n2);
    readout.textContent = `At θ = ${theta.toFixed(2)}°   Rs = ${point.s.toFixed(4)}   Rp = ${point.p.toFixed(4)}   `
      + `unpolarized mean = ${point.mean.toFixed(4)}`;
    noteNumbers.textContent = explain(point, theta, n1, n2);
  }

  /** The sentence with this angle's numbers. */
  function explain({ s, p, mean }, theta, n1, n2) {
    if (n1 === n2) return 'Here n₁ = n₂: there is no interface and nothing reflects.';
    if (s - mean < 5e-5) {
      return `At ${theta.toFixed(2)}° the two agree (Rs = ${s.toFixed(4)}, mean = ${mean.toFixed(4)}): `
        + (p > 0.9999 ? 'everything is reflected.' : 's and p reflect alike there.');
    }
    return `At ${theta.toFixed(2)}°: Rs = ${s.toFixed(4)} against the unpolarized ${mean.toFixed(4)}, `
      + `${(s / mean).toFixed(2)} times too high (Rp = ${p.toFixed(4)}).`;
  }
  update();

  return {
    plot,
    get point() { return point; },
    update,
    describe() {
      const { n1, n2, theta } = values;
      return `From n₁ = ${n1} into n₂ = ${n2}: at ${theta.toFixed(2)}° Rs = ${point.s.toFixed(4)}, `
        + `Rp = ${point.p.toFixed(4)} and their mean, the unpolarized R, is ${point.mean.toFixed(4)}; `
        + `Rp is 0 at the Brewster angle ${brewster.toFixed(2)}°`
        + (critical === null ? '.' : `; past the critical angle ${critical.toFixed(2)}° both are 1.`);
    },
    csv() {
      return {
        filename: `polarization-n1${values.n1}-n2${values.n2}.csv`,
        columns: { theta_deg: curves.theta, Rs: curves.s, Rp: curves.p, R_unpolarized: curves.exact },
      };
    },
    /** The plot on the panel's background (uPlot's canvas is transparent). */
    png: () => plot.toPng(),
    dispose() {
      plot.dispose();
      panel.remove();
    },
  };
}
