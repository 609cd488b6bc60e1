// Everything the normal-mips panel derives from its controls before it can draw: the analytic
// map sampled at level 0, every technique's chain (buildChain) and the packed arrays that
// the GPU is given (uploadLevels). Pure; it runs in chain workers (chainWorker.js), each on a
// share of the techniques (splitTechniques), or, where there are none, on the calling thread.
// Packing is part of it because at 1024² it costs about as much as the chains themselves.
import { buildChain } from './buildChain.js';
import { createNormalMap } from './createNormalMap.js';
import { buildMomentPyramid } from './momentPyramid.js';
import { sampleLevel0 } from './sampleLevel0.js';
import { TECHNIQUES } from './techniqueLayout.js';
import { uploadLevels } from './uploadLevels.js';

/**
 * buildChainsFor({ kind, params, size, precision, channels, techniques = all }) →
 * { pyramid, chains, uploads, ms } for those techniques: uploads[technique] is
 * uploadLevels(chains[technique]); Toksvig stores exactly what naive stores, so it shares naive's
 * chain arrays and packing (it must come with naive). ms: the time it all took, from `now`.
 */
export function buildChainsFor({ kind, params, size, precision, channels, techniques = TECHNIQUES }, now = () => performance.now()) {
  if (techniques.includes('toksvig') && !techniques.includes('naive')) throw new RangeError('toksvig is built with naive');
  const t0 = now();
  const normals = sampleLevel0(createNormalMap(kind, params), size);
  const pyramid = buildMomentPyramid(normals, size);
  const chains = {};
  const uploads = {};
  for (const technique of TECHNIQUES.filter((t) => techniques.includes(t))) {
    if (technique === 'toksvig') {
      chains.toksvig = { ...chains.naive, technique };
      uploads.toksvig = uploads.naive;
    } else {
      chains[technique] = buildChain(pyramid, technique, { precision, channels });
      uploads[technique] = uploadLevels(chains[technique]);
    }
  }
  return { pyramid, chains, uploads, ms: now() - t0 };
}

// Shares of about equal work (values written per texel: chain components + packed components).
const SPLITS = {
  1: [TECHNIQUES],
  2: [['naive', 'toksvig', 'renormalized', 'clean'], ['lean', 'vmf']],
  3: [['naive', 'toksvig', 'renormalized'], ['lean'], ['clean', 'vmf']],
};

/** The techniques of each of `parts` builds (1 to 3; more gain nothing: 5 distinct chains). */
export function splitTechniques(parts) {
  return SPLITS[Math.min(3, Math.max(1, Math.floor(parts) || 1))];
}

/** One build from the parts' results (same request, disjoint techniques): pyramid from the first. */
export function mergeBuilds(parts) {
  const chains = {};
  const uploads = {};
  for (const technique of TECHNIQUES) {
    const part = parts.find((p) => p.chains[technique]);
    if (!part) throw new RangeError(`no part built ${technique}`);
    chains[technique] = part.chains[technique];
    uploads[technique] = part.uploads[technique];
  }
  return { pyramid: parts[0].pyramid, chains, uploads, ms: Math.max(...parts.map((p) => p.ms)) };
}

/** The distinct ArrayBuffers of a build, for a zero-copy postMessage (shared arrays once). */
export function transferablesOf({ pyramid, chains, uploads = {} }) {
  const buffers = new Set(pyramid ? pyramid.map((level) => level.data.buffer) : []);
  for (const chain of Object.values(chains)) for (const level of chain.levels) buffers.add(level.data.buffer);
  for (const list of Object.values(uploads)) for (const { mipmaps } of list) for (const m of mipmaps) buffers.add(m.data.buffer);
  return [...buffers];
}
