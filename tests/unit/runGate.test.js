import { describe, expect, it } from 'vitest';
import { createRunGate, isStaleRun } from '../../src/panels/shared/createRunGate.js';

describe('createRunGate', () => {
  it('makes a run stale when a newer one begins, and only then', () => {
    const gate = createRunGate();
    const first = gate.begin();
    expect(first.live).toBe(true);
    const second = gate.begin();
    expect(first.live).toBe(false);
    expect(first.signal.aborted).toBe(true);
    expect(second.live).toBe(true);
  });

  it('cancel stales the current run and lets the next start live', () => {
    const gate = createRunGate();
    const run = gate.begin();
    gate.cancel('context lost');
    expect(run.live).toBe(false);
    expect(() => run.throwIfStale()).toThrow('context lost');
    expect(gate.begin().live).toBe(true);
  });

  it('dispose stales the current run and every later one', () => {
    const gate = createRunGate();
    const run = gate.begin();
    gate.dispose();
    expect(run.live).toBe(false);
    expect(gate.begin().live).toBe(false);
  });

  it('tells a stale run’s error from any other', async () => {
    const gate = createRunGate();
    const run = gate.begin();
    const waiting = new Promise((_, reject) => run.signal.addEventListener('abort', () => reject(run.signal.reason)));
    gate.begin();
    const error = await waiting.catch((e) => e);
    expect(isStaleRun(error)).toBe(true);
    expect(isStaleRun(new Error('shader refused'))).toBe(false);
  });
});
