// @ts-check
// lil-gui controls generated from a params schema. The schema is the single source of truth and
// the host owns the values: a controller edits a draft copy and hands each change to the host
// (validated there), which then writes the draft back and refreshes the controller.
// Each control's name and each option's are the panel's words from the catalogue (controlText.js).
import GUI from 'lil-gui';
import { phoneWidth } from '../ui/phoneWidth.js';
import { controlLabel, optionLabel } from '../panels/controlText.js';
import { localNumberInput } from './localNumberInput.js';

/** @typedef {import('lil-gui').Controller} Controller */

/**
 * lil-gui's options ({ label: value }) for panel `id`'s enum `key`, in the page's language.
 * @param {string} id
 * @param {string} key
 * @param {import('./panelContract.js').EnumSpec} spec
 * @returns {Record<string, string>}
 */
export function guiOptions(id, key, spec) {
  const values = Array.isArray(spec.options) ? spec.options : Object.keys(spec.options);
  return Object.fromEntries(values.map((value) => [optionLabel(id, key, value), value]));
}

/**
 * Adds one controller per key in `keys` to `gui`, editing `draft` (a copy of panel `id`'s values).
 * onChange(key, value) runs on every change; returns { key: controller }.
 * @param {GUI} gui  a lil-gui root or folder
 * @param {string} id
 * @param {import('./panelContract.js').Schema} schema
 * @param {import('./panelContract.js').Values} draft
 * @param {(key: string, value: unknown) => void} onChange
 * @param {string[]} [keys]
 * @returns {Record<string, Controller>}
 */
export function bindGui(gui, id, schema, draft, onChange, keys = Object.keys(schema)) {
  /** @type {Record<string, Controller>} */
  const controllers = Object.create(null);
  for (const key of keys) {
    const spec = schema[key];
    if (!spec) throw new Error(`bindGui: ${key} is not in the schema`);
    let controller;
    if (spec.type === 'number') localNumberInput(controller = gui.add(draft, key, spec.min, spec.max, spec.step));
    else if (spec.type === 'enum') controller = gui.add(draft, key, guiOptions(id, key, spec));
    else if (spec.type === 'color') controller = gui.addColor(draft, key);
    else controller = gui.add(draft, key);
    controller.name(controlLabel(id, key)).onChange((/** @type {unknown} */ value) => onChange(key, value));
    controllers[key] = controller;
  }
  return controllers;
}

/**
 * A GUI placed inside the panel (not floating over the page), keyboard-operable like any form.
 * @param {HTMLElement} container
 * @param {string} title
 */
export function createPanelGui(container, title) {
  const gui = new GUI({ container, title, width: 360, injectStyles: false }); // styles.css imports its CSS
  // On a phone: a drawer under the picture, opened by its title.
  if (typeof window.matchMedia === 'function' && phoneWidth().matches) gui.close();
  return gui;
}
