import { describe, expect, it } from 'vitest';
import { parseMessage } from '../../src/host/messageApi.js';

describe('message API shapes', () => {
  it('accepts set with a params object and get', () => {
    expect(parseMessage({ type: 'fresnel-lab:set', params: { nT: 2 } })).toEqual({ kind: 'set', params: { nT: 2 } });
    expect(parseMessage({ type: 'fresnel-lab:get' })).toEqual({ kind: 'get' });
  });
  it('ignores everything else', () => {
    for (const data of [null, undefined, 'fresnel-lab:get', 42, [], { type: 'fresnel-lab:set' },
      { type: 'fresnel-lab:set', params: 'nT=2' }, { type: 'fresnel-lab:set', params: [1] },
      { type: 'fresnel-lab:ready' }, { type: 'other' }, { params: {} }]) {
      expect(parseMessage(data)).toBeNull();
    }
  });
});
