// @ts-check
// The figure a prediction is made on: θ from 0° to 90° across, with a marker the student drags or
// moves with the keys (a slider to assistive technology). Before the truth is shown it holds only
// the axis, so it gives nothing away; shown, it draws the question's curve, the true angle and the
// prediction beside it, both labelled, and the marker stays where it was committed. SVG, so it is
// sharp on a projector and needs no WebGL.
import { el } from '../../ui/el.js';
import { angle, fixed } from '../../ui/format.js';
import { number } from '../questionParts.js';
import english from 'virtual:messages/en/homework';
import { messages } from '../../i18n/messages.js';

const t = messages('homework', english);

const NS = 'http://www.w3.org/2000/svg';
const W = 640;
const H = 240;
const PAD = { left: 48, right: 24, top: 20, bottom: 52 };
const x = (/** @type {number} */ t) => PAD.left + ((W - PAD.left - PAD.right) * t) / 90;
/** @type {(tag: string, attrs?: Record<string, string | number>) => SVGElement} */
const svg = (tag, attrs = {}) => {
  const node = document.createElementNS(NS, tag);
  for (const [k, v] of Object.entries(attrs)) node.setAttribute(k, String(v));
  return node;
};

/**
 * label: the accessible name of the slider; describedBy: the id of the question's text; axisTitle: what
 * the 0°–90° axis measures (a question's own, else the angle from the normal), and axisInText: the
 * same as a sentence names it (θ where the axis is the angle from the normal).
 * onChange(value) while it moves. Returns { element, value(), setValue(v), lock({ committed }),
 * showTruth({ curve, truth }), hideTruth(), focus() }.
 * @param {{ label: string, describedBy?: string | null, axisTitle?: string, axisInText?: string, initial?: number,
 *   onChange?: (value: number) => void }} options
 */
export function createPredictFigure({
  label, describedBy = null, axisTitle = t('predict.thetaAxis'), axisInText = 'θ', initial = 45, onChange = () => {},
}) {
  const element = el('figure', 'predict-figure');
  const picture = svg('svg', { viewBox: `0 0 ${W} ${H}`, class: 'predict-svg', 'aria-hidden': 'false' });
  const axis = svg('g', { class: 'predict-axis', 'aria-hidden': 'true' });
  const baseline = H - PAD.bottom;
  axis.append(svg('line', { x1: x(0), x2: x(90), y1: baseline, y2: baseline }));
  for (let t = 0; t <= 90; t += 15) {
    axis.append(svg('line', { x1: x(t), x2: x(t), y1: baseline, y2: baseline + 6 }));
    const tick = svg('text', { x: x(t), y: baseline + 22, 'text-anchor': 'middle' });
    tick.textContent = `${t}°`;
    axis.append(tick);
  }
  const title = svg('text', { x: x(90), y: baseline + 46, 'text-anchor': 'end', class: 'predict-axis-title' });
  title.textContent = axisTitle;
  axis.append(title);
  const truthLayer = svg('g', { class: 'predict-truth', 'aria-hidden': 'true' });
  const marker = svg('g', { class: 'predict-marker', tabindex: 0, role: 'slider' });
  const markerLine = svg('line', { y1: PAD.top, y2: baseline });
  const knob = svg('circle', { r: 11, cy: baseline });
  const markerText = svg('text', { y: baseline - 18, 'text-anchor': 'middle' }); // low: the truth is labelled at the top
  marker.append(markerLine, knob, markerText);
  marker.setAttribute('aria-label', label);
  if (describedBy) marker.setAttribute('aria-describedby', describedBy);
  marker.setAttribute('aria-valuemin', '0');
  marker.setAttribute('aria-valuemax', '90');
  picture.append(axis, truthLayer, marker);
  const caption = el('figcaption', 'predict-caption', t('predict.howTo'));
  element.append(picture, caption);

  let value = initial;
  let locked = false;
  let committed = false;
  const draw = () => {
    const px = x(value);
    for (const line of [markerLine]) { line.setAttribute('x1', String(px)); line.setAttribute('x2', String(px)); }
    knob.setAttribute('cx', String(px));
    markerText.setAttribute('x', String(Math.min(Math.max(px, PAD.left + 40), W - PAD.right - 40)));
    markerText.textContent = committed ? t('predict.yours', { angle: angle(value, 1) }) : angle(value, 1);
    marker.style.display = locked && !committed ? 'none' : ''; // revealed with nothing committed: no marker
    marker.setAttribute('aria-valuenow', value.toFixed(1));
    marker.setAttribute('aria-valuetext', t('predict.valueText', { angle: fixed(value, 1) }));
  };
  const setValue = (/** @type {number} */ v, notify = true) => {
    if (locked || !Number.isFinite(v)) return;
    value = Math.round(Math.min(90, Math.max(0, v)) * 10) / 10;
    draw();
    if (notify) onChange(value);
  };
  marker.addEventListener('keydown', (event) => {
    const step = event.shiftKey ? 0.1 : 1;
    /** @type {Record<string, number>} */
    const moves = { ArrowRight: step, ArrowUp: step, ArrowLeft: -step, ArrowDown: -step, PageUp: 10, PageDown: -10 };
    if (Object.hasOwn(moves, event.key)) setValue(value + moves[event.key]);
    else if (event.key === 'Home') setValue(0);
    else if (event.key === 'End') setValue(90);
    else return;
    event.preventDefault();
  });
  const fromPointer = (/** @type {PointerEvent} */ event) => {
    const box = picture.getBoundingClientRect();
    const scale = W / box.width;
    setValue((((event.clientX - box.left) * scale - PAD.left) / (W - PAD.left - PAD.right)) * 90);
  };
  picture.addEventListener('pointerdown', (event) => {
    if (locked) return;
    picture.setPointerCapture?.(event.pointerId);
    fromPointer(event);
    marker.focus();
  });
  picture.addEventListener('pointermove', (event) => { if (!locked && picture.hasPointerCapture?.(event.pointerId)) fromPointer(event); });
  draw();

  return {
    element,
    value: () => value,
    setValue: (/** @type {number} */ v) => setValue(v, false),
    focus: () => marker.focus(),
    /**
     * committed: whether the marker holds the student's prediction (else the truth came first).
     * @param {{ committed?: boolean }} [options]
     */
    lock({ committed: made = true } = {}) {
      locked = true;
      committed = made;
      marker.setAttribute('aria-disabled', 'true');
      if (!made) marker.setAttribute('tabindex', '-1');
      element.classList.add('locked');
      caption.textContent = made ? t('predict.committed') : t('predict.shownFirst');
      draw();
    },
    /** Back to the axis alone (lecture mode switched on again): the prediction stays. */
    hideTruth() {
      truthLayer.replaceChildren();
      element.classList.remove('revealed');
      if (locked) caption.textContent = committed ? t('predict.committed') : caption.textContent;
    },
    /**
     * curve: { label, f(θ°), level? }; truth: the true angle in degrees.
     * @param {{ curve: import('../questionParts.js').Curve, truth: number }} shown
     */
    showTruth({ curve, truth }) {
      truthLayer.replaceChildren();
      const samples = Array.from({ length: 361 }, (_, i) => i / 4);
      const ys = samples.map(curve.f);
      const top = Math.max(curve.level ?? 0, ...ys) || 1;
      const y = (/** @type {number} */ v) => baseline - ((baseline - PAD.top - 14) * v) / top;
      const path = samples.map((t, i) => `${i ? 'L' : 'M'}${x(t).toFixed(1)},${y(ys[i]).toFixed(1)}`).join('');
      truthLayer.append(svg('path', { d: path, class: 'predict-curve' }));
      if (curve.level !== undefined) {
        truthLayer.append(svg('line', { x1: x(0), x2: x(90), y1: y(curve.level), y2: y(curve.level), class: 'predict-level' }));
      }
      truthLayer.append(svg('line', { x1: x(truth), x2: x(truth), y1: PAD.top, y2: baseline, class: 'predict-true' }));
      const name = svg('text', {
        x: x(truth) + (truth > 60 ? -6 : 6), y: PAD.top + 12, 'text-anchor': truth > 60 ? 'end' : 'start', class: 'predict-true-label',
      });
      name.textContent = t('predict.true', { angle: angle(truth, 2) });
      // The curve's name goes top left, or low on the left where the curve starts high there.
      const highOnLeft = Math.max(...ys.slice(0, 145)) > 0.7 * top;
      const curveName = svg('text', { x: PAD.left + 6, y: highOnLeft ? baseline - 40 : PAD.top + 30, class: 'predict-curve-label' });
      curveName.textContent = curve.level === undefined ? curve.label
        : t('predict.curveLevel', { label: curve.label, level: number(curve.level) });
      truthLayer.append(name, curveName);
      element.classList.add('revealed');
      const shown = { label: curve.label, axis: axisInText, truth: angle(truth, 2) };
      caption.textContent = committed ? t('predict.againstYours', { ...shown, yours: angle(value, 1) }) : t('predict.against', shown);
    },
  };
}
