import { describe, expect, it } from 'vitest';
import { parseMessage } from '../../src/ui/messageApi.js';
import { lecturePrefix } from '../../src/ui/shareLinks.js';
import { PANEL_CATALOGUE } from '../../src/panels/registry.js';

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

describe('panel ids and URL prefixes', () => {
  it('the catalogue holds the fixed ids in lecture order', () => {
    expect(PANEL_CATALOGUE).toEqual([
      'spheres', 'normal-mips', 'asphalt', 'changing-specular', 'reflect-refract', 'refraction-waves',
      'angle-ratio', 'refractive-index', 'polarization', 'exact-fresnel', 'schlick', 'r0-derivation',
      'fresnel-lighting', 'metals', 'speed-accuracy', 'stability',
    ]);
  });
  it('the hero owns the short keys; other panels prefix theirs', () => {
    expect(lecturePrefix('spheres')).toBe('');
    expect(lecturePrefix('metals')).toBe('metals.');
  });
});
