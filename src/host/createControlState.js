// @ts-check
// Which of a panel's controls a deck has locked (shown, not editable) or hidden: by the message
// API (lock, unlock, hide, show) or the embed URL (&lock=nI,nT, &hide=…, &controls=0). The host
// asks it before applying a change made in the panel, and applies it to the controllers of every
// mount, so the state outlives a remount.
import { resolveKey } from './params.js';

/**
 * What a deck does to controls: lock, unlock, hide or show.
 * @typedef {'lock' | 'unlock' | 'hide' | 'show'} ControlChange
 */

/**
 * What the state needs of a control (a lil-gui controller).
 * @typedef {{ enable(on: boolean): unknown, show(on: boolean): unknown }} Control
 */

/**
 * shell: the panel's frame (its class no-controls hides the whole control column).
 * @param {import('./panelContract.js').Schema} schema
 * @param {{ classList: { toggle(name: string, on: boolean): unknown } }} shell
 */
export function createControlState(schema, shell) {
  /** @type {Set<string>} */
  const locked = new Set();
  /** @type {Set<string>} */
  const hidden = new Set();
  /** @type {Record<string, Control>} */
  let controllers = {};
  /** @type {{ controller: Control, keys: string[] }[]} */
  let tied = []; // controls that are not a schema key but change some (a preset, a swap button)

  function apply() {
    for (const [key, controller] of Object.entries(controllers)) {
      controller.enable(!locked.has(key));
      controller.show(!hidden.has(key));
    }
    for (const { controller, keys } of tied) {
      controller.enable(!keys.some((k) => locked.has(k)));
      controller.show(!keys.every((k) => hidden.has(k)));
    }
  }

  return {
    /**
     * kind: lock, unlock, hide or show; names: keys or aliases, or null for every control (for
     * hide and show, the whole control column). Returns the names that are not controls.
     * @param {ControlChange} kind
     * @param {readonly string[] | null} names
     * @returns {string[]}
     */
    change(kind, names) {
      if (names === null && (kind === 'hide' || kind === 'show')) {
        shell.classList.toggle('no-controls', kind === 'hide');
        if (kind === 'show') hidden.clear();
        apply();
        return [];
      }
      const unknown = [];
      for (const name of names ?? Object.keys(schema)) {
        const key = resolveKey(schema, name);
        if (key === undefined) unknown.push(name);
        else if (kind === 'lock') locked.add(key);
        else if (kind === 'unlock') locked.delete(key);
        else if (kind === 'hide') hidden.add(key);
        else hidden.delete(key);
      }
      apply();
      return unknown;
    },
    /** A new mount: its controllers come next. */
    clear() {
      controllers = {};
      tied = [];
    },
    /**
     * The controllers of this mount ({ key: lil-gui controller }), kept in step from now on.
     * @param {Record<string, Control>} made
     */
    bind(made) {
      controllers = made;
      apply();
    },
    /**
     * A control that changes `keys`: locked when any of them is, hidden when all of them are.
     * @template {Control} C
     * @param {C} controller
     * @param {string[]} keys
     * @returns {C}
     */
    tie(controller, keys) {
      tied.push({ controller, keys });
      apply();
      return controller;
    },
    isLocked: (/** @type {string} */ key) => locked.has(key),
    get locked() { return [...locked]; },
    get hidden() { return [...hidden]; },
  };
}
