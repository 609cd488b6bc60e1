// Everything the normal-mips panel derives from its controls before it can draw: the analytic
// map sampled at level 0, every technique's chain (buildAllChains) and the packed arrays that
// three.js uploads (uploadLevels). Pure; it runs in the chain worker (chainWorker.js) or, where
// there is no worker, on the calling thread. Packing is part of it because at 1024² it costs
// about as much as the chains themselves.
import { buildAllChains } from './buildChain.js';
import { createNormalMap } from './createNormalMap.js';
import { sampleLevel0 } from './sampleLevel0.js';
import { uploadLevels } from './uploadLevels.js';

/**
 * buildChainsFor({ kind, params, size, precision, channels }) → { pyramid, chains, uploads, ms }:
 * uploads[technique] is uploadLevels(chains[technique]) (Toksvig shares naive's, as its chain
 * does); ms the time it all took, from `now` (ms clock, injectable).
 */
export function buildChainsFor({ kind, params, size, precision, channels }, now = () => performance.now()) {
  const t0 = now();
  const normals = sampleLevel0(createNormalMap(kind, params), size);
  const { pyramid, chains } = buildAllChains(normals, size, { precision, channels });
  const uploads = {};
  for (const [technique, chain] of Object.entries(chains)) {
    uploads[technique] = technique === 'toksvig' && uploads.naive ? uploads.naive : uploadLevels(chain);
  }
  return { pyramid, chains, uploads, ms: now() - t0 };
}

/** The distinct ArrayBuffers of a build, for a zero-copy postMessage (shared arrays once). */
export function transferablesOf({ pyramid, chains, uploads = {} }) {
  const buffers = new Set(pyramid.map((level) => level.data.buffer));
  for (const chain of Object.values(chains)) for (const level of chain.levels) buffers.add(level.data.buffer);
  for (const list of Object.values(uploads)) for (const { mipmaps } of list) for (const m of mipmaps) buffers.add(m.data.buffer);
  return [...buffers];
}
