// The DOM of the reflect-refract panel: the stage (canvas, centre mark, caption), the lecture's
// three captions with the current one marked, the R/T bar for the centre ray, its numbers and
// the blend formula with live values. Styles: styles.css (all under .rr-panel).
import english from 'virtual:messages/en/reflect-refract';
import { messages } from '../../i18n/messages.js';
import { renderTex, texNumber } from '../../ui/tex.js';
import { texText } from '../../ui/texText.js';
import { REFLECTION_BANDS } from './physics.js';
import { bandLabel } from './words.js';
import { el } from '../../ui/el.js';
import { definitionList } from '../../ui/definitionList.js';
import { angle, fixed, tickLabel } from '../../ui/format.js';
import { makeScrollBox } from '../../ui/scrollBox.js';
import { lectureNote } from '../../ui/lectureNote.js';
import { schema } from './schema.js';

const t = messages('reflect-refract', english);

/** A bound of R between the captions (0, 0.1, 0.4) as shown. */
const bound = (/** @type {number} */ r) => tickLabel(r, 0.1);

export function buildReflectRefractDom(host) {
  const root = el('div', 'rr-panel');
  const stage = el('div', 'rr-stage');
  const canvas = el('canvas', 'rr-canvas');
  canvas.setAttribute('role', 'img');
  canvas.setAttribute('aria-label', t('canvasLabel'));
  const mark = el('div', 'rr-mark');
  mark.setAttribute('aria-hidden', 'true');
  const caption = el('div', 'rr-caption');
  caption.setAttribute('aria-hidden', 'true');
  stage.append(canvas, mark, caption);

  const bands = el('ol', 'rr-bands');
  bands.setAttribute('aria-label', t('bandsLabel'));
  const bandItems = Object.fromEntries(REFLECTION_BANDS.map((band, i) => {
    const item = el('li', '', bandLabel(band));
    const lower = i === 0 ? 0 : REFLECTION_BANDS[i - 1].below;
    item.title = Number.isFinite(band.below)
      ? t('bandRange', { low: bound(lower), high: bound(band.below) })
      : t('bandFrom', { low: bound(lower) });
    bands.append(item);
    return [band.id, item];
  }));

  const bar = el('div', 'rr-bar');
  bar.setAttribute('aria-hidden', 'true');
  const barR = el('span', 'rr-bar-r');
  const barT = el('span', 'rr-bar-t');
  bar.append(barR, barT);
  const summary = definitionList('rr-summary');
  const formula = makeScrollBox(el('div', 'rr-formula'), t('formulaBox'));
  root.append(stage, bands, bar, summary.element, formula);
  const note = lectureNote(root);
  host.append(root);

  return {
    stage,
    canvas,
    /** ray: the centreRay() result for the current view. */
    show(ray) {
      caption.textContent = bandLabel(ray.band);
      for (const [bandId, item] of Object.entries(bandItems)) {
        const current = bandId === ray.band.id;
        item.classList.toggle('rr-current', current);
        if (current) item.setAttribute('aria-current', 'true');
        else item.removeAttribute('aria-current');
      }
      barR.style.flexGrow = String(ray.R);
      barT.style.flexGrow = String(ray.T);
      barR.textContent = ray.R >= 0.12 ? `R ${fixed(ray.R, 3)}` : '';
      barT.textContent = ray.T >= 0.12 ? `T ${fixed(ray.T, 3)}` : '';
      summary.set([
        [t('summary.theta'), `θ = ${angle(ray.thetaDeg)}`],
        [t('summary.reflected'), `R = ${fixed(ray.R, 4)}`],
        [t('summary.refracted'), `T = 1 − R = ${fixed(ray.T, 4)}`],
        [t('summary.floor'), `T/n_t² = ${fixed(ray.floorWeight, 4)}`],
        [t('summary.transmitted'), t('summary.transmittedValue', { theta: angle(ray.thetaTDeg) })],
      ]);
      const w = (/** @type {string} */ key) => `\\text{${texText(t(key))}}`;
      const sky = `${w('formula.sky')}_{${w('formula.reflected')}}`;
      const floor = `${w('formula.floor')}_{${w('formula.refracted')}}`;
      renderTex(formula, `\\begin{aligned}${w('formula.colour')} &= R\\,${sky} + \\tfrac{T}{n_t^2}\\,${floor}`
        + `\\\\ &= ${texNumber(ray.R)}\\,${sky} + ${texNumber(ray.floorWeight)}\\,${floor}\\end{aligned}`);
    },
    /** The note on the lecture's "No reflection" caption, for a surface of index n with head-on reflectance r0. */
    setNote(n, r0) {
      const little = REFLECTION_BANDS[0].below;
      const args = { n: tickLabel(n, schema.nT.step), r0: fixed(r0, 3), little: bound(little), spread: fixed(1 / (n * n), 2) };
      note.set(t(n === 1 ? 'noteNoInterface' : r0 >= little ? 'noteStrong' : 'note', args), t('noteSource'));
    },
  };
}
