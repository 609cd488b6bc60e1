// definitionList in Node: a small stand-in for the few DOM calls it makes (createElement, className,
// textContent, dataset, append, replaceChildren), enough to read back the tree it builds.
import { describe, it, expect, beforeAll, afterAll } from 'vitest';
import { definitionList } from '../../src/ui/definitionList.js';

class FakeNode {
  constructor(tag) {
    this.tagName = tag.toUpperCase();
    this.className = '';
    this.dataset = {};
    this.children = [];
    this.text = '';
  }

  set textContent(value) { this.children = []; this.text = String(value); }

  get textContent() { return this.text + this.children.map((c) => (typeof c === 'string' ? c : c.textContent)).join(''); }

  append(...nodes) { this.children.push(...nodes); }

  replaceChildren(...nodes) { this.text = ''; this.children = nodes; }
}

/** The tree as plain data: tag, class, data-*, text of leaves. */
const shape = (node) => (typeof node === 'string' ? node : {
  tag: node.tagName.toLowerCase(),
  ...(node.className ? { class: node.className } : {}),
  ...(Object.keys(node.dataset).length ? { data: { ...node.dataset } } : {}),
  ...(node.children.length ? { children: node.children.map(shape) } : { text: node.text }),
});

let saved;
beforeAll(() => {
  saved = globalThis.document;
  globalThis.document = /** @type {any} */ ({ createElement: (tag) => new FakeNode(tag) });
});
afterAll(() => { globalThis.document = saved; });

describe('definitionList', () => {
  it('builds one <div> per row holding a <dt> and its <dd>', () => {
    const list = definitionList('rr-summary');
    list.set([['Reflected (sky)', 'R = 0.0204'], ['Transmitted angle', 'θt = 28.13°', 'is-key']]);
    expect(shape(list.element)).toEqual({
      tag: 'dl', class: 'rr-summary', children: [
        { tag: 'div', children: [{ tag: 'dt', text: 'Reflected (sky)' }, { tag: 'dd', text: 'R = 0.0204' }] },
        { tag: 'div', class: 'is-key', children: [{ tag: 'dt', text: 'Transmitted angle' }, { tag: 'dd', text: 'θt = 28.13°' }] },
      ],
    });
  });

  it('replaces its rows on every set', () => {
    const list = definitionList('summary');
    list.set([['a', '1'], ['b', '2'], ['c', '3']]);
    list.set([['d', '4']]);
    expect(list.element.children).toHaveLength(1);
    expect(list.element.textContent).toBe('d4');
  });

  it('adds rows whose <dd> the caller keeps, with the value class and data attributes', () => {
    const list = definitionList('sk-readout', { valueClass: 'sk-value' });
    const exact = list.add('Exact', { out: 'exact' });
    const plain = list.add('Schlick');
    exact.textContent = '0.0400';
    expect(shape(list.element).children).toEqual([
      { tag: 'div', children: [{ tag: 'dt', text: 'Exact' }, { tag: 'dd', class: 'sk-value', data: { out: 'exact' }, text: '0.0400' }] },
      { tag: 'div', children: [{ tag: 'dt', text: 'Schlick' }, { tag: 'dd', class: 'sk-value', text: '' }] },
    ]);
    expect(plain).toBe(list.element.children[1].children[1]);
  });

  it('writes terms and values through the given writer (the lecture\'s subscripts)', () => {
    const calls = [];
    const list = definitionList('rw-summary', { write: (node, text) => { calls.push([node.tagName, text]); node.textContent = `<${text}>`; } });
    list.set([['Incidence θ_i', '45.00°']]);
    expect(calls).toEqual([['DT', 'Incidence θ_i'], ['DD', '45.00°']]);
    expect(list.element.textContent).toBe('<Incidence θ_i><45.00°>');
  });
});
