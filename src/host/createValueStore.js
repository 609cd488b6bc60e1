// @ts-check
// The values of one panel and every change to them, without the DOM. Every write is checked
// against the schema (params.js); a change made in the panel that touches a key a deck has locked
// is refused whole; what changed is passed on in a fixed order: the controls, the panel's redraw,
// then whatever follows a settled change (the description, the URL) and last the listeners (the
// message API). The host (createPanelHost.js) gives the hooks; tests give plain functions.
import { applyParams, resolveKey } from './params.js';

/** @typedef {import('./panelContract.js').Schema} Schema */
/** @typedef {import('./panelContract.js').Values} Values */
/** @typedef {import('./panelContract.js').ChangeSource} ChangeSource */
/** @typedef {import('./panelContract.js').SetResult} SetResult */
/** @typedef {import('./params.js').Problem} Problem */
/** @typedef {{ keys: string[], source: ChangeSource }} Change */

/**
 * What the store tells its owner. Every hook is optional.
 * @typedef {object} StoreHooks
 * @property {(key: string) => boolean} [isLocked]  a deck has locked this key's control
 * @property {(keys: string[]) => void} [show]  the controls show these keys' values again (changed, or a value refused)
 * @property {(problems: Problem[]) => void} [refused]  values that were rejected: said on screen
 * @property {(keys: string[]) => void} [redraw]  the panel redraws for these keys; never called from inside itself
 * @property {(keys: string[], source: ChangeSource) => void} [settled]  once per change, after every redraw it caused
 */

/** A view of `values` that can be read but not written: panels change values through the host. */
function readOnly(/** @type {Values} */ values, /** @type {string} */ id) {
  /** @type {(target: Values, key: string | symbol) => never} */
  const refuse = (_target, key) => {
    throw new TypeError(`The ${id} panel wrote values.${String(key)}: panels change values with ctx.set().`);
  };
  return /** @type {Readonly<Values>} */ (new Proxy(values, { set: refuse, deleteProperty: refuse, defineProperty: refuse }));
}

/**
 * @param {string} id  the panel's id (named by the error a write to `values` throws)
 * @param {Schema} schema
 * @param {Values} start  values already checked against the schema (copied)
 * @param {StoreHooks} [hooks]
 */
export function createValueStore(id, schema, start, hooks = {}) {
  const { isLocked = () => false, show = () => {}, refused = () => {}, redraw = () => {}, settled = () => {} } = hooks;
  /** @type {Values} */
  const values = { ...start };
  /** @type {Set<(change: Change) => void>} */
  const listeners = new Set();
  // A change made while the panel redraws (a set inside redraw) waits for that redraw to end, then
  // redraws in turn: redraw never runs inside itself, and what follows a change (settled, the
  // listeners) runs once, with every key, and the source of the change that started it.
  let redrawing = false;
  /** @type {string[]} */
  let waiting = [];
  let quiet = 0;

  /** @param {string[]} keys @param {ChangeSource} source */
  function changed(keys, source) {
    show(keys);
    if (redrawing) {
      waiting.push(...keys);
      return;
    }
    const all = new Set(keys);
    redrawing = true;
    try {
      redraw(keys);
      while (waiting.length) {
        const next = [...new Set(waiting)];
        waiting = [];
        next.forEach((key) => all.add(key));
        redraw(next);
      }
    } finally {
      redrawing = false;
      waiting = [];
    }
    settled([...all], source);
    if (!quiet) for (const listener of listeners) listener({ keys: [...all], source });
  }

  return {
    /** The current values, read-only (writing one throws). */
    values: readOnly(values, id),
    /**
     * Validated partial update; keys may be aliases. source: 'user' (a control or the panel), 'api'
     * (a message), 'page' (the page-wide material). A change not made by the API that touches a
     * locked key (a swap of n_i and n_t with n_t locked) is refused whole: `refused` is true.
     * @param {Record<string, unknown> | null | undefined} update
     * @param {{ source?: ChangeSource }} [options]
     * @returns {SetResult}
     */
    set(update, { source = 'api' } = {}) {
      const touchesLocked = source !== 'api' && Object.keys(update ?? {}).some((name) => {
        const key = resolveKey(schema, name);
        return key !== undefined && isLocked(key);
      });
      const result = { ...applyParams(schema, values, touchesLocked ? {} : update), refused: touchesLocked };
      if (result.rejected.length) {
        refused(result.rejected);
        const kept = result.rejected.map(({ key }) => key).filter((key) => Object.hasOwn(values, key));
        if (kept.length) show(kept);
      }
      if (result.changed.length) changed(result.changed, source);
      return result;
    },
    /**
     * listener({ keys, source }) after every change, once its redraws are done; returns a function
     * that removes it.
     * @param {(change: Change) => void} listener
     */
    onChange(listener) {
      listeners.add(listener);
      return () => { listeners.delete(listener); };
    },
    /**
     * Runs fn; what it sets reaches the controls, the redraw and `settled` but no listener. Where a
     * panel starts (a set during its mount) is not a change: a deck learns those values from ready.
     * @template T
     * @param {() => T} fn
     * @returns {T}
     */
    quietly(fn) {
      quiet += 1;
      try {
        return fn();
      } finally {
        quiet -= 1;
      }
    },
  };
}
