import { describe, expect, it } from 'vitest';
import { API_VERSION, parseMessage } from '../../src/host/messageApi.js';
import { EMBED_KEYS, parseOrigin, readEmbedOptions } from '../../src/host/readEmbedOptions.js';

describe('message API shapes', () => {
  it('accepts set with a params object and get', () => {
    expect(parseMessage({ type: 'fresnel-lab:set', params: { nT: 2 } })).toEqual({ kind: 'set', params: { nT: 2 } });
    expect(parseMessage({ type: 'fresnel-lab:get' })).toEqual({ kind: 'get' });
    expect(parseMessage({ type: 'fresnel-lab:audio', on: true })).toEqual({ kind: 'audio', on: true });
    expect(parseMessage({ type: 'fresnel-lab:audio', on: 'yes' })).toBeNull();
  });
  it('accepts the version 1 messages, with their defaults', () => {
    expect(API_VERSION).toBe(1);
    expect(parseMessage({ type: 'fresnel-lab:reset' })).toEqual({ kind: 'reset', to: 'start' });
    expect(parseMessage({ type: 'fresnel-lab:reset', to: 'defaults' })).toEqual({ kind: 'reset', to: 'defaults' });
    expect(parseMessage({ type: 'fresnel-lab:snapshot', width: 640, id: 7 })).toEqual({ kind: 'snapshot', width: 640, height: null, id: '7' });
    expect(parseMessage({ type: 'fresnel-lab:lock', keys: ['nT', 'nI'] })).toEqual({ kind: 'lock', keys: ['nT', 'nI'] });
    expect(parseMessage({ type: 'fresnel-lab:hide' })).toEqual({ kind: 'hide', keys: null });
    expect(parseMessage({ type: 'fresnel-lab:theme', theme: 'light' })).toEqual({ kind: 'theme', theme: 'light' });
    expect(parseMessage({ type: 'fresnel-lab:projector', on: true })).toEqual({ kind: 'projector', on: true });
    expect(parseMessage({ type: 'fresnel-lab:reducedMotion', on: false })).toEqual({ kind: 'reducedMotion', on: false });
    expect(parseMessage({ type: 'fresnel-lab:pause' })).toEqual({ kind: 'pause' });
    // reveal.js posts plain strings to the iframes of the slide it enters and leaves.
    expect(parseMessage('slide:start')).toEqual({ kind: 'resume' });
    expect(parseMessage('slide:stop')).toEqual({ kind: 'pause' });
  });
  it('ignores everything else', () => {
    for (const data of [null, undefined, 'fresnel-lab:get', 42, [], { type: 'fresnel-lab:set' },
      { type: 'fresnel-lab:set', params: 'nT=2' }, { type: 'fresnel-lab:set', params: [1] },
      { type: 'fresnel-lab:ready' }, { type: 'fresnel-lab:key' }, { type: 'other' }, { params: {} },
      { type: 'fresnel-lab:reset', to: 'now' }, { type: 'fresnel-lab:snapshot', width: 0 },
      { type: 'fresnel-lab:snapshot', height: 5000 }, { type: 'fresnel-lab:snapshot', width: 1.5 },
      { type: 'fresnel-lab:lock', keys: 'nT' }, { type: 'fresnel-lab:lock', keys: [3] },
      { type: 'fresnel-lab:lock', keys: Array(65).fill('a') }, { type: 'fresnel-lab:theme', theme: 'Light' },
      { type: 'fresnel-lab:projector', on: 1 }, 'slide:shown', { type: 'fresnel-lab:__proto__' }]) {
      expect(parseMessage(data)).toBeNull();
    }
  });
});

describe('embed options in the URL', () => {
  const read = (query) => readEmbedOptions(new URLSearchParams(query));
  it('reads the look, the controls and the deck origin', () => {
    expect(read('panel=spheres&theme=light&projector=1&reducedMotion=0&audio=1&lock=nI,%20nT&hide=kd&controls=0&fit=1'
      + '&parentOrigin=https://deck.example:8443/'))
      .toEqual({
        options: {
          theme: 'light', projector: true, reducedMotion: false, audio: true, lock: ['nI', 'nT'], hide: ['kd'], controls: false, fit: true,
          parentOrigin: 'https://deck.example:8443',
        },
        problems: [],
      });
    expect(read('panel=spheres').options).toEqual({
      theme: null, projector: null, reducedMotion: null, audio: false, lock: [], hide: [], controls: true, fit: false, parentOrigin: null,
    });
  });
  it('names what it cannot use and leaves it out; an unusable parentOrigin lets no page in', () => {
    const { options, problems } = read('theme=blue&projector=yes&parentOrigin=javascript:alert(1)');
    expect(options).toMatchObject({ theme: null, projector: null, parentOrigin: 'none' });
    expect(problems.map((p) => p.key)).toEqual(['theme', 'projector', 'parentOrigin']);
  });
  it('takes http(s) origins in any spelling of an origin, and nothing else', () => {
    expect(parseOrigin('https://a.example')).toBe('https://a.example');
    expect(parseOrigin('https://A.Example:443/')).toBe('https://a.example');
    expect(parseOrigin('http://127.0.0.1:5173')).toBe('http://127.0.0.1:5173');
    for (const raw of ['https://a.example/deck', 'https://a.example/?x', 'https://a.example#top', 'file:///x', 'null', '*', 'a.example',
      'https://user@a.example']) expect(parseOrigin(raw), raw).toBeNull();
  });
  it('no panel uses a name the embed page reads for itself', async () => {
    const { PANELS } = await import('../../src/panels/manifest.js');
    const { readdirSync } = await import('node:fs');
    const ids = readdirSync(new URL('../../src/panels/', import.meta.url)).filter((d) => PANELS.some((p) => p.id === d));
    for (const id of ids) {
      const { schema } = await import(`../../src/panels/${id}/schema.js`);
      const names = Object.entries(schema).flatMap(([key, spec]) => [key, ...(spec.aliases ?? [])]);
      expect(names.filter((n) => EMBED_KEYS.includes(n)), id).toEqual([]);
    }
    expect(ids).toHaveLength(PANELS.length);
  });
});
