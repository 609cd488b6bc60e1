// Term/value rows as every panel shows them: a <dl> whose rows are each a <div> holding one <dt>
// and its <dd> (the grouping HTML allows inside a <dl>). A stylesheet lays the rows out as flex
// items, or as the rows of a grid with `div { display: contents; }`.
import { el } from './el.js';

/** @typedef {(node: HTMLElement, text: string) => unknown} WriteText */

/** @type {WriteText} */
const plainText = (node, text) => { node.textContent = text; };

/**
 * @param {string} className the <dl>'s class
 * @param {{ valueClass?: string, write?: WriteText }} [options] valueClass: every <dd>'s class;
 *   write: how a term or a value becomes the cell's content (setSubscripted for the lecture's n_i)
 */
export function definitionList(className, { valueClass = '', write = plainText } = {}) {
  const list = /** @type {HTMLDListElement} */ (el('dl', className));

  /** @param {string} term @param {string} value @param {string} [rowClass] */
  function row(term, value, rowClass) {
    const wrap = el('div', rowClass);
    const dt = el('dt');
    const dd = el('dd', valueClass);
    write(dt, term);
    write(dd, value);
    wrap.append(dt, dd);
    return { wrap, dd };
  }

  return {
    element: list,
    /**
     * Adds a row whose value is written later, and returns its <dd>. data: the <dd>'s data-*
     * attributes (what tests and styles find it by).
     * @param {string} term
     * @param {Record<string, string>} [data]
     */
    add(term, data = {}) {
      const { wrap, dd } = row(term, '');
      Object.assign(dd.dataset, data);
      list.append(wrap);
      return dd;
    },
    /**
     * Replaces every row: [term, value] or [term, value, the row's class].
     * @param {string[][]} rows
     */
    set(rows) {
      list.replaceChildren(...rows.map(([term, value, rowClass]) => row(term, value, rowClass).wrap));
    },
  };
}
