import { describe, expect, it } from 'vitest';
import { currentOwner, ownedBy } from '../../src/gl/faultOwner.js';
import { onDemand } from '../../src/gl/onDemand.js';

const owner = (name) => ({ name, fail() {}, contextLost() {}, contextRestored() {} });

describe('ownedBy: whose code runs now', () => {
  it('is the owner inside, the one around it after, and nobody outside', () => {
    const a = owner('a');
    const b = owner('b');
    expect(currentOwner()).toBeNull();
    ownedBy(a, () => {
      expect(currentOwner()).toBe(a);
      ownedBy(b, () => expect(currentOwner()).toBe(b));
      expect(currentOwner()).toBe(a);
    });
    expect(currentOwner()).toBeNull();
  });

  it('is given back when the code throws', () => {
    expect(() => ownedBy(owner('a'), () => { throw new Error('x'); })).toThrow('x');
    expect(currentOwner()).toBeNull();
  });
});

describe('onDemand: a draw that throws is its owner’s fault', () => {
  it('reports to the owner it was made under, and keeps drawing later requests', () => {
    const queue = [];
    globalThis.requestAnimationFrame = (fn) => queue.push(fn);
    const failures = [];
    const faults = { ...owner('p'), fail: (error) => failures.push(error.message) };
    let calls = 0;
    const frames = ownedBy(faults, () => onDemand(() => {
      calls += 1;
      if (calls === 1) throw new Error('first draw failed');
    }));
    frames.request();
    queue.shift()();
    expect(failures).toEqual(['first draw failed']);
    frames.request();
    queue.shift()();
    expect(calls).toBe(2);
    expect(frames.frames).toBe(2);
    delete globalThis.requestAnimationFrame;
  });
});
