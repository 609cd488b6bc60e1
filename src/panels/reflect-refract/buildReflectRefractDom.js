// The DOM of the reflect-refract panel: the stage (canvas, centre mark, caption), the lecture's
// three captions with the current one marked, the R/T bar for the centre ray, its numbers and
// the blend formula with live values. Styles: styles.css (all under .rr-panel).
import { renderTex, texNumber } from '../../ui/tex.js';
import { REFLECTION_BANDS } from './model.js';
import { el } from '../../ui/el.js';
import { definitionList } from '../../ui/definitionList.js';
import { angle, fixed } from '../../ui/format.js';
import { makeScrollBox } from '../../ui/scrollBox.js';

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
        ['Transmitted angle', `θt = ${angle(ray.thetaTDeg)}`],
      ]);
      renderTex(formula, `\\text{colour} = ${texNumber(ray.R)}\\,\\text{sky}_{\\text{reflect}}`
        + ` + ${texNumber(ray.T)}\\,\\text{floor}_{\\text{refract}}`);
    },
  };
}
