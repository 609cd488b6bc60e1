// The DOM of the reflect-refract panel: the stage (canvas, centre mark, caption), the lecture's
// three captions with the current one marked, the R/T bar for the centre ray, its numbers and
// the blend formula with live values. Styles: styles.css (all under .rr-panel).
import { renderTex, texNumber } from '../../ui/tex.js';
import { REFLECTION_BANDS } from './model.js';
import { el } from '../../ui/el.js';
import { definitionList } from '../../ui/definitionList.js';
import { angle, fixed } from '../../ui/format.js';
import { makeScrollBox } from '../../ui/scrollBox.js';
import { lectureNote } from '../../ui/lectureNote.js';

const NOTE_SOURCE = 'Hecht, Optics, 5th ed., §4.6; Pharr, Jakob & Humphreys, Physically Based Rendering, 3rd ed., §16.1.3';

export function buildReflectRefractDom(host) {
  const root = el('div', 'rr-panel');
  const stage = el('div', 'rr-stage');
  const canvas = el('canvas', 'rr-canvas');
  canvas.setAttribute('role', 'img');
  canvas.setAttribute('aria-label',
    'A flat water surface seen from above: the reflected sky and the refracted tiled pool floor, blended by Fresnel reflectance. '
    + 'The ring marks the centre ray.');
  const mark = el('div', 'rr-mark');
  mark.setAttribute('aria-hidden', 'true');
  const caption = el('div', 'rr-caption');
  caption.setAttribute('aria-hidden', 'true');
  stage.append(canvas, mark, caption);

  const bands = el('ol', 'rr-bands');
  bands.setAttribute('aria-label', 'How much reflection the centre of the view shows');
  const bandItems = Object.fromEntries(REFLECTION_BANDS.map((band, i) => {
    const item = el('li', '', band.label);
    const lower = i === 0 ? 0 : REFLECTION_BANDS[i - 1].below;
    item.title = Number.isFinite(band.below) ? `R from ${lower} to ${band.below}` : `R of ${lower} or more`;
    bands.append(item);
    return [band.id, item];
  }));

  const bar = el('div', 'rr-bar');
  bar.setAttribute('aria-hidden', 'true');
  const barR = el('span', 'rr-bar-r');
  const barT = el('span', 'rr-bar-t');
  bar.append(barR, barT);
  const summary = definitionList('rr-summary');
  const formula = makeScrollBox(el('div', 'rr-formula'), 'Reflected and transmitted fractions');
  root.append(stage, bands, bar, summary.element, formula);
  const note = lectureNote(root);
  host.append(root);

  return {
    stage,
    canvas,
    /** ray: the centreRay() result for the current view. */
    show(ray) {
      caption.textContent = ray.band.label;
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
        ['Centre ray from the normal', `θ = ${angle(ray.thetaDeg)}`],
        ['Reflected (sky)', `R = ${fixed(ray.R, 4)}`],
        ['Refracted (floor)', `T = 1 − R = ${fixed(ray.T, 4)}`],
        ['Floor radiance let out', `T/n_t² = ${fixed(ray.floorWeight, 4)}`],
        ['Transmitted angle', `θt = ${angle(ray.thetaTDeg)}`],
      ]);
      renderTex(formula, '\\begin{aligned}\\text{colour} &= R\\,\\text{sky}_{\\text{reflect}} '
        + '+ \\tfrac{T}{n_t^2}\\,\\text{floor}_{\\text{refract}}'
        + `\\\\ &= ${texNumber(ray.R)}\\,\\text{sky}_{\\text{reflect}} + ${texNumber(ray.floorWeight)}\\,\\text{floor}_{\\text{refract}}`
        + '\\end{aligned}');
    },
    /** The note on the lecture's "No reflection" caption, for a surface of index n with head-on reflectance r0. */
    setNote(n, r0) {
      const caption = n === 1
        ? 'The lecture captions the steepest view "No reflection". With n_t = 1 there is no interface, and nothing is '
          + 'reflected at any angle, so none of the lecture\'s captions applies; any other surface reflects something head-on, '
          + 'so below R = 0.1 the panel says "little reflection".'
        : r0 >= 0.1
          ? `The lecture captions the steepest view "No reflection", but no view reflects nothing: this surface (n_t = ${n}) `
            + `reflects R = ${fixed(r0, 3)} even head-on, so no view of it is captioned "little reflection"; the steepest reads `
            + `"some reflection". The floor also looks dimmer from the air than from inside the medium: its light spreads into a `
            + `wider cone as it leaves, which divides its radiance by n_t² (${fixed(1 / (n * n), 2)} here) on top of T.`
          : `The lecture captions the steepest view "No reflection", but no view reflects nothing: head-on this surface `
          + `(n_t = ${n}) still reflects R = ${fixed(r0, 3)} of the light, so below R = 0.1 the panel says "little reflection" `
          + '(the captions sort the views by R alone, not by which layer looks brighter). '
          + `The floor also looks dimmer from the air than from inside the medium: its light spreads into a wider cone as it `
          + `leaves, which divides its radiance by n_t² (${fixed(1 / (n * n), 2)} here) on top of T.`;
      note.set(caption, NOTE_SOURCE);
    },
  };
}
