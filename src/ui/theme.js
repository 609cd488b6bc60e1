// @ts-check
// Theme: dark or light, and a projector mode (larger type, thicker lines, stronger contrast).
// Remembered in localStorage; a change fires `fresnel-lab:theme` so plots can redraw.
import { own } from '../host/own.js';

const KEY = 'fresnel-lab:theme';

/**
 * The theme this browser keeps (anything stored is read as untrusted text: the defaults where it is not one).
 * @returns {Theme}
 */
export function loadTheme() {
  try {
    /** @type {unknown} */
    const saved = JSON.parse(localStorage.getItem(KEY) ?? '{}');
    return { scheme: own(saved, 'scheme') === 'light' ? 'light' : 'dark', projector: own(saved, 'projector') === true };
  } catch {
    return { scheme: 'dark', projector: false };
  }
}

/** @typedef {{ scheme: 'dark' | 'light', projector: boolean }} Theme */

/**
 * remember: false for a theme an embed was told to use, which is not the reader's choice.
 * @param {Theme} theme
 * @param {{ remember?: boolean }} [options]
 */
export function applyTheme(theme, { remember = true } = {}) {
  const root = document.documentElement;
  root.dataset.theme = theme.scheme;
  root.classList.toggle('projector', theme.projector);
  try {
    if (remember) localStorage.setItem(KEY, JSON.stringify(theme));
  } catch {
    // Private mode or a blocked storage: the theme still applies for this visit.
  }
  window.dispatchEvent(new CustomEvent('fresnel-lab:theme', { detail: theme }));
}

/**
 * A CSS custom property of the page, read at draw time so canvases follow the theme.
 * @param {string} name
 */
export function cssVar(name, fallback = '#888') {
  return getComputedStyle(document.documentElement).getPropertyValue(name).trim() || fallback;
}

/** Line widths grow in projector mode. */
export function lineScale() {
  return document.documentElement.classList.contains('projector') ? 1.6 : 1;
}
