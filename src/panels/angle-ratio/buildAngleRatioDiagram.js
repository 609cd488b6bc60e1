// The SVG ray diagram of the angle-ratio panel: a flat interface, the normal, and the incident,
// reflected and refracted rays whose stroke widths are proportional to the power they carry.
// The incident ray's end is a slider (drag it, or focus it and use the arrow keys).
import english from 'virtual:messages/en/angle-ratio';
import { messages } from '../../i18n/messages.js';
import { DEG } from '../../optics/angles.js';
import { setSubscripted } from '../../ui/subscripts.js';
import { angle, fixed, markupNumber } from '../../ui/format.js';

const t = messages('angle-ratio', english);
const NS = 'http://www.w3.org/2000/svg';
const W = 800;
const H = 520;
const P = { x: 400, y: 290 }; // point of incidence
const LEN = 200; // drawn length of each ray
const MAX_WIDTH = 30; // stroke width of the incident ray (power 1)

function svgEl(tag, attrs = {}, text) {
  const node = document.createElementNS(NS, tag);
  for (const [k, v] of Object.entries(attrs)) node.setAttribute(k, v);
  if (text !== undefined) node.textContent = text;
  return node;
}

/** A point at distance r from P along a direction given by its angle from the upward normal. */
const up = (deg, r, side) => ({ x: P.x + side * r * Math.sin(deg * DEG), y: P.y - r * Math.cos(deg * DEG) });
const down = (deg, r, side) => ({ x: P.x + side * r * Math.sin(deg * DEG), y: P.y + r * Math.cos(deg * DEG) });

/** An arc of radius r around P from the normal (start) to point `end`; sweep 0 or 1 (SVG arc flag). */
function arcPath(start, end, r, sweep) {
  const [x0, y0, x1, y1] = [start.x, start.y, end.x, end.y].map((v) => markupNumber(v, 2));
  return `M${x0} ${y0} A${r} ${r} 0 0 ${sweep} ${x1} ${y1}`;
}

function ray(className, label) {
  const g = svgEl('g', { class: `ar-ray ${className}` });
  const guide = svgEl('line', { class: 'ar-guide' });
  const band = svgEl('line', { class: 'ar-band' });
  const arrow = svgEl('path', { class: 'ar-arrow' });
  const text = svgEl('text', { class: 'ar-ray-label' }, label);
  g.append(guide, band, arrow, text);
  return {
    g,
    text,
    /** From a to b with stroke width ∝ power; the arrowhead sits at the middle, pointing to b. */
    set(a, b, power, caption, anchor) {
      for (const line of [guide, band]) {
        line.setAttribute('x1', a.x); line.setAttribute('y1', a.y);
        line.setAttribute('x2', b.x); line.setAttribute('y2', b.y);
      }
      band.setAttribute('stroke-width', markupNumber(Math.max(0, power * MAX_WIDTH), 3));
      const dx = b.x - a.x;
      const dy = b.y - a.y;
      const len = Math.hypot(dx, dy);
      const ux = dx / len;
      const uy = dy / len;
      const m = { x: (a.x + b.x) / 2 + ux * 12, y: (a.y + b.y) / 2 + uy * 12 };
      const s = 13; // arrowhead size, fixed so a faint ray still shows its direction
      arrow.setAttribute('d', `M${m.x} ${m.y} L${m.x - ux * s * 1.6 - uy * s} ${m.y - uy * s * 1.6 + ux * s} `
        + `L${m.x - ux * s * 1.6 + uy * s} ${m.y - uy * s * 1.6 - ux * s} Z`);
      text.textContent = caption;
      text.setAttribute('x', anchor.x);
      text.setAttribute('y', anchor.y);
      text.setAttribute('text-anchor', anchor.end ? 'end' : 'start');
    },
  };
}

export function buildAngleRatioDiagram(host, { onAngle }) {
  const svg = svgEl('svg', { viewBox: `0 0 ${W} ${H}`, class: 'ar-svg', role: 'group' });
  svg.append(svgEl('title', {}, t('diagramTitle')));
  const lower = svgEl('rect', { class: 'ar-medium2', x: 0, y: P.y, width: W, height: H - P.y });
  const surface = svgEl('line', { class: 'ar-surface', x1: 0, y1: P.y, x2: W, y2: P.y });
  const normal = svgEl('line', { class: 'ar-normal', x1: P.x, y1: 12, x2: P.x, y2: H - 12 });
  const nILabel = svgEl('text', { class: 'ar-medium-label', x: 16, y: 34 });
  const nTLabel = svgEl('text', { class: 'ar-medium-label', x: 16, y: H - 54 });
  const arcs = ['ar-arc-i', 'ar-arc-r', 'ar-arc-t'].map((c) => svgEl('path', { class: `ar-arc ${c}` }));
  const arcLabels = ['ar-arc-i', 'ar-arc-r', 'ar-arc-t'].map((c) => svgEl('text', { class: `ar-arc-label ${c}` }));
  const incident = ray('ar-incident', t('ray.incident'));
  const reflected = ray('ar-reflected', t('ray.reflected'));
  const refracted = ray('ar-refracted', t('ray.refracted'));
  const tirNote = svgEl('text', { class: 'ar-tir', x: W / 2 + 20, y: P.y + 60 });

  // The slider: a ring at the incident ray's start.
  const handle = svgEl('g', {
    class: 'ar-handle', tabindex: 0, role: 'slider', 'aria-label': t('handleLabel'),
    'aria-valuemin': 0, 'aria-valuemax': 90, 'aria-orientation': 'horizontal',
  });
  const focusRing = svgEl('circle', { class: 'ar-handle-focus', r: 27 });
  const knob = svgEl('circle', { class: 'ar-handle-knob', r: 17 });
  handle.append(focusRing, knob);

  svg.append(lower, surface, normal, ...arcs, ...arcLabels, incident.g, reflected.g, refracted.g,
    nILabel, nTLabel, tirNote, handle);
  host.append(svg);

  // Pointer: the angle between the normal and the line from P to the pointer (upper-left quadrant).
  const angleAt = (event) => {
    const matrix = svg.getScreenCTM();
    if (!matrix) return null;
    const pt = new DOMPoint(event.clientX, event.clientY).matrixTransform(matrix.inverse());
    const deg = Math.atan2(Math.max(0, P.x - pt.x), Math.max(0, P.y - pt.y)) / DEG;
    return Math.min(90, Math.max(0, deg));
  };
  let dragging = false;
  const onDown = (event) => {
    dragging = true;
    handle.setPointerCapture?.(event.pointerId);
    handle.focus();
    event.preventDefault();
  };
  const onMove = (event) => {
    if (!dragging) return;
    const deg = angleAt(event);
    if (deg !== null) onAngle(deg);
  };
  const onUp = () => { dragging = false; };
  let current = 0;
  const onKey = (event) => {
    const big = event.shiftKey ? 5 : 1;
    const steps = { ArrowRight: big, ArrowUp: big, ArrowLeft: -big, ArrowDown: -big, PageUp: 10, PageDown: -10 };
    let next = null;
    if (event.key in steps) next = current + steps[event.key];
    else if (event.key === 'Home') next = 0;
    else if (event.key === 'End') next = 90;
    if (next === null) return;
    event.preventDefault();
    onAngle(Math.min(90, Math.max(0, next)));
  };
  handle.addEventListener('pointerdown', onDown);
  handle.addEventListener('pointermove', onMove);
  handle.addEventListener('pointerup', onUp);
  handle.addEventListener('pointercancel', onUp);
  handle.addEventListener('keydown', onKey);

  return {
    svg,
    handle,
    /** split: from interfaceSplit; nI, nT: the indices. */
    set(split, nI, nT) {
      const { theta, R, T, thetaT, tir, critical } = split;
      current = theta;
      setSubscripted(nILabel, t('mediumI', { n: fixed(nI, 4), theta: angle(theta, 1) }));
      setSubscripted(nTLabel, t('mediumT', { n: fixed(nT, 4), tir: tir ? 'yes' : 'no', thetaT: tir ? '' : angle(thetaT) }));
      const start = up(theta, LEN, -1);
      // Ray captions sit in the corners, colour-coded, so they never cross a ray or an arc; none
      // shares a line with a medium's label, so a longer language does not run one into the other.
      incident.set(start, P, 1, t('captionIncident'), { x: 16, y: 72 });
      const rEnd = up(theta, LEN, 1);
      reflected.set(P, rEnd, R, t('captionReflected', { R: fixed(R, 3) }), { x: W - 16, y: 72, end: true });
      refracted.g.style.display = tir ? 'none' : '';
      if (!tir) {
        const tEnd = down(thetaT, LEN, 1);
        refracted.set(P, tEnd, T, t('captionRefracted', { T: fixed(T, 3) }), { x: W - 16, y: H - 16, end: true });
      }
      tirNote.textContent = tir ? t('tirNote', { theta: angle(theta, 1), critical: angle(critical) }) : '';
      handle.setAttribute('transform', `translate(${markupNumber(start.x, 2)} ${markupNumber(start.y, 2)})`);
      handle.setAttribute('aria-valuenow', markupNumber(theta, 1));
      handle.setAttribute('aria-valuetext', t('handleValue', { theta: angle(theta, 1), R: fixed(R, 3), T: fixed(T, 3) }));

      const r = 70;
      arcs[0].setAttribute('d', theta > 0.05 ? arcPath(up(0, r, 1), up(theta, r, -1), r, 0) : '');
      arcs[1].setAttribute('d', theta > 0.05 ? arcPath(up(0, r + 14, 1), up(theta, r + 14, 1), r + 14, 1) : '');
      arcs[2].setAttribute('d', !tir && thetaT > 0.05 ? arcPath(down(0, r, 1), down(thetaT, r, 1), r, 0) : '');
      const place = (node, at, text) => {
        node.setAttribute('x', markupNumber(at.x, 1));
        node.setAttribute('y', markupNumber(at.y, 1));
        setSubscripted(node, text);
      };
      // Short names just outside each arc: inside the wedge when it is wide enough, else beside
      // the ray, so a label never sits on a ray (the values are in the corner labels).
      const at = (deg) => (deg >= 36 ? deg / 2 : deg + 22);
      place(arcLabels[0], up(at(theta), r + 26, -1), theta > 0.05 ? t('arcI') : '');
      place(arcLabels[1], up(at(theta), r + 26, 1), theta > 0.05 ? t('arcI') : '');
      place(arcLabels[2], down(at(thetaT ?? 0), r + 26, 1), !tir && thetaT > 0.05 ? t('arcT') : '');
    },
    dispose() {
      handle.removeEventListener('pointerdown', onDown);
      handle.removeEventListener('pointermove', onMove);
      handle.removeEventListener('pointerup', onUp);
      handle.removeEventListener('pointercancel', onUp);
      handle.removeEventListener('keydown', onKey);
    },
  };
}

const COPIED = ['fill', 'fill-opacity', 'stroke', 'stroke-width', 'stroke-opacity', 'stroke-dasharray', 'opacity',
  'font-size', 'font-family', 'font-weight', 'text-anchor', 'dominant-baseline', 'display', 'paint-order'];

/**
 * A PNG data URL of the SVG as shown. The theme's CSS variables do not reach an SVG drawn as an
 * image, so the computed style of every element is written inline into a copy first.
 */
export function svgToPng(svg, background, scale = 2) {
  const copy = svg.cloneNode(true);
  const from = [svg, ...svg.querySelectorAll('*')];
  const to = [copy, ...copy.querySelectorAll('*')];
  from.forEach((node, i) => {
    const style = getComputedStyle(node);
    // Through the CSSOM: a style attribute written as text is refused by the page's CSP.
    for (const p of COPIED) to[i].style.setProperty(p, style.getPropertyValue(p));
  });
  copy.setAttribute('width', W);
  copy.setAttribute('height', H);
  const url = `data:image/svg+xml;charset=utf-8,${encodeURIComponent(new XMLSerializer().serializeToString(copy))}`;
  return new Promise((resolve, reject) => {
    const image = new Image();
    image.onload = () => {
      const canvas = document.createElement('canvas');
      canvas.width = W * scale;
      canvas.height = H * scale;
      const c2d = canvas.getContext('2d');
      c2d.fillStyle = background;
      c2d.fillRect(0, 0, canvas.width, canvas.height);
      c2d.drawImage(image, 0, 0, canvas.width, canvas.height);
      resolve(canvas.toDataURL('image/png'));
    };
    image.onerror = () => reject(new Error('the diagram could not be drawn as an image'));
    image.src = url;
  });
}
