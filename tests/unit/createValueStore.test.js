// The host's value store (src/host/createValueStore.js) without a browser: what a set applies and
// refuses, the order in which a change reaches the controls, the panel and the listeners, sets made
// while the panel redraws, locks, and values that only the store writes.
import { describe, expect, it } from 'vitest';
import { createValueStore } from '../../src/host/createValueStore.js';
import { createControlState } from '../../src/host/createControlState.js';
import { schema, start } from './everyKindSchema.js';

/** A store whose hooks write what they were told into `log`, in order; `also` adds to or replaces them. */
function logged(also = {}) {
  const log = [];
  const hooks = {
    show: (keys) => log.push(['show', keys]),
    refused: (problems) => log.push(['refused', problems.map((p) => p.key)]),
    redraw: (keys) => log.push(['redraw', keys]),
    settled: (keys, source) => log.push(['settled', keys, source]),
    ...also,
  };
  const store = createValueStore('test', schema, start, hooks);
  store.onChange((change) => log.push(['listener', change.keys, change.source]));
  return { store, log };
}

describe('a set', () => {
  it('applies valid values and passes the change on: controls, redraw, settled, then listeners', () => {
    const { store, log } = logged();
    const result = store.set({ nT: 2, method: 'schlick' }, { source: 'user' });
    expect(result).toEqual({ applied: { nT: 2, method: 'schlick' }, rejected: [], changed: ['nT', 'method'], refused: false });
    expect(store.values).toMatchObject({ nT: 2, method: 'schlick', nI: 1 });
    expect(log).toEqual([
      ['show', ['nT', 'method']],
      ['redraw', ['nT', 'method']],
      ['settled', ['nT', 'method'], 'user'],
      ['listener', ['nT', 'method'], 'user'],
    ]);
  });

  it('is a change made by the API unless it says otherwise', () => {
    const { store, log } = logged();
    store.set({ nI: 1.2 });
    expect(log.at(-1)).toEqual(['listener', ['nI'], 'api']);
  });

  it('that changes nothing tells nobody', () => {
    const { store, log } = logged();
    expect(store.set({ nT: 1.5, spin: 'false' }).changed).toEqual([]);
    expect(log).toEqual([]);
  });

  it('takes older names and writes the value under its key', () => {
    const { store } = logged();
    expect(store.set({ n2: '2.5' }).changed).toEqual(['nT']);
    expect(store.values.nT).toBe(2.5);
    expect(Object.hasOwn(store.values, 'n2')).toBe(false);
  });

  it('refuses bad values by name, keeps the old value, and has the controls show it again', () => {
    const { store, log } = logged();
    const result = store.set({ nT: 9, count: 2.5, method: 'fast', nI: 1.25 }, { source: 'user' });
    expect(result.rejected.map((p) => [p.key, p.raw, p.reason])).toEqual([
      ['nT', 9, 'is outside 1 to 3'],
      ['count', 2.5, 'is not a whole number'],
      ['method', 'fast', 'is not one of exact, schlick'],
    ]);
    expect(store.values).toMatchObject({ nT: 1.5, count: 4, method: 'exact', nI: 1.25 }); // the valid part still applies
    expect(log.slice(0, 3)).toEqual([['refused', ['nT', 'count', 'method']], ['show', ['nT', 'count', 'method']], ['show', ['nI']]]);
  });

  it('refuses names the schema does not have, inherited ones included, and shows no control for them', () => {
    const { store, log } = logged();
    const update = JSON.parse('{"__proto__": {"nT": 2}, "constructor": 1, "nope": true}');
    expect(store.set(update).rejected.map((p) => p.key)).toEqual(['__proto__', 'constructor', 'nope']);
    expect(log).toEqual([['refused', ['__proto__', 'constructor', 'nope']]]);
    expect(store.values.nT).toBe(1.5);
    expect(Object.keys(store.values)).toEqual(Object.keys(schema));
  });
});

describe('a set while the panel redraws', () => {
  it('waits for that redraw to end, then redraws in turn: one listener call with every key', () => {
    const depth = { now: 0, most: 0 };
    const seen = [];
    const { store, log } = logged({
      redraw(keys) {
        depth.now += 1;
        depth.most = Math.max(depth.most, depth.now);
        log.push(['redraw', keys]);
        if (keys.includes('nI')) {
          store.set({ nT: 2 }, { source: 'user' });
          seen.push(store.values.nT); // applied at once; only the redraw waits
          store.set({ nT: 2.5, count: 8 }, { source: 'user' });
        }
        if (keys.includes('count')) store.set({ spin: true }, { source: 'user' });
        depth.now -= 1;
      },
    });
    store.set({ nI: 1.2 }, { source: 'api' });
    expect(depth.most).toBe(1);
    expect(seen).toEqual([2]);
    expect(log).toEqual([
      ['show', ['nI']],
      ['redraw', ['nI']],
      ['show', ['nT']],
      ['show', ['nT', 'count']],
      ['redraw', ['nT', 'count']], // the waiting keys once each
      ['show', ['spin']],
      ['redraw', ['spin']],
      ['settled', ['nI', 'nT', 'count', 'spin'], 'api'],
      ['listener', ['nI', 'nT', 'count', 'spin'], 'api'], // the source of the change that started it
    ]);
    expect(store.values).toMatchObject({ nI: 1.2, nT: 2.5, count: 8, spin: true });
  });

  it('after a redraw that threw, the next change redraws again', () => {
    let fail = true;
    const { store, log } = logged({
      redraw(keys) {
        log.push(['redraw', keys]);
        if (fail) throw new Error('broken picture');
      },
    });
    expect(() => store.set({ nI: 1.2 })).toThrow('broken picture');
    fail = false;
    store.set({ nI: 1.3 });
    expect(log.filter(([what]) => what !== 'show').slice(-3)).toEqual([
      ['redraw', ['nI']], ['settled', ['nI'], 'api'], ['listener', ['nI'], 'api'],
    ]);
  });

  it('from a listener is a change of its own', () => {
    const { store, log } = logged();
    const stop = store.onChange(({ keys }) => { if (keys.includes('nI')) store.set({ nT: 2 }, { source: 'page' }); });
    store.set({ nI: 1.2 }, { source: 'user' });
    stop();
    expect(log.filter(([what]) => what === 'listener')).toEqual([['listener', ['nI'], 'user'], ['listener', ['nT'], 'page']]);
  });
});

describe('listeners', () => {
  it('are each called once per change, until removed', () => {
    const { store } = logged();
    const calls = { a: 0, b: 0 };
    const stopA = store.onChange(() => { calls.a += 1; });
    store.onChange(() => { calls.b += 1; });
    store.set({ nI: 1.1 });
    stopA();
    store.set({ nI: 1.2 });
    expect(calls).toEqual({ a: 1, b: 2 });
  });

  it('hear nothing set quietly (where a panel starts), though the controls, the picture and settled do', () => {
    const { store, log } = logged();
    const made = store.quietly(() => {
      store.set({ nI: 1.2 }, { source: 'user' });
      return 'instance';
    });
    expect(made).toBe('instance');
    expect(log).toEqual([['show', ['nI']], ['redraw', ['nI']], ['settled', ['nI'], 'user']]);
    expect(() => store.quietly(() => { throw new Error('mount failed'); })).toThrow('mount failed');
    store.set({ nI: 1.3 });
    expect(log.at(-1)).toEqual(['listener', ['nI'], 'api']); // quiet ends, even after a throw
  });
});

describe('locked keys', () => {
  const lockable = () => {
    const controls = createControlState(schema, { classList: { toggle() {} } });
    const { store, log } = logged({ isLocked: controls.isLocked });
    return { controls, store, log };
  };

  it('refuse a change made in the panel that touches one, whole, under any of its names', () => {
    const { controls, store, log } = lockable();
    expect(controls.change('lock', ['n2'])).toEqual([]);
    for (const update of [{ nT: 2 }, { nI: 1.2, nT: 2 }, { n2: 2 }]) {
      for (const source of ['user', 'page']) {
        expect(store.set(update, { source })).toEqual({ applied: {}, rejected: [], changed: [], refused: true });
      }
    }
    expect(store.values).toMatchObject({ nI: 1, nT: 1.5 });
    expect(log).toEqual([]);
    expect(store.set({ nI: 1.2, nope: 1 }, { source: 'user' }).refused).toBe(false); // other keys are free
  });

  it('change when the deck changes them, and again in the panel once unlocked', () => {
    const { controls, store } = lockable();
    controls.change('lock', null);
    expect(store.set({ nT: 2 }, { source: 'api' })).toMatchObject({ changed: ['nT'], refused: false });
    controls.change('unlock', ['nT']);
    expect(store.set({ nT: 2.5 }, { source: 'user' })).toMatchObject({ changed: ['nT'], refused: false });
    expect(store.set({ nI: 2 }, { source: 'user' }).refused).toBe(true);
  });
});

describe('the values', () => {
  it('are read, never written, from outside the store, and follow every set', () => {
    const { store } = logged();
    const { values } = store;
    expect(() => { values.nT = 2; }).toThrow(/test panel wrote values\.nT: panels change values with ctx\.set\(\)/);
    expect(() => { delete values.nT; }).toThrow(TypeError);
    expect(() => Object.defineProperty(values, 'x', { value: 1 })).toThrow(TypeError);
    store.set({ nT: 2 });
    expect(values.nT).toBe(2);
  });

  it('are the store\'s own: the start it was given is copied', () => {
    const mine = { ...start };
    const store = createValueStore('test', schema, mine);
    store.set({ nT: 2 });
    mine.nI = 3;
    expect(mine.nT).toBe(1.5);
    expect(store.values.nI).toBe(1);
  });
});
