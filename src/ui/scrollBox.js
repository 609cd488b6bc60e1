// A box that scrolls sideways when what it holds is wider than a phone (a table, a formula, a
// listing). It takes the focus, so a keyboard can scroll it too (WCAG 2.1.1; axe's
// scrollable-region-focusable), and it is a named region, so a screen reader says what it is.
import { el } from './el.js';

/** Makes `box` such a box, named `label`; returns it. */
export function makeScrollBox(box, label) {
  box.classList.add('scroll-x');
  box.tabIndex = 0;
  box.setAttribute('role', 'region');
  box.setAttribute('aria-label', label);
  return box;
}

/** A new such box around `child`. */
export function scrollBox(child, label) {
  const box = makeScrollBox(el('div'), label);
  box.append(child);
  return box;
}
