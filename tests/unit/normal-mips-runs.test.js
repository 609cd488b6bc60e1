import { describe, expect, it } from 'vitest';
import { createNormalMipsRuns } from '../../src/panels/normal-mips/runs.js';
import {
  chainRequest, lightPlacement, mapParams, mergeKeys, sceneSettings,
} from '../../src/panels/normal-mips/sceneSettings.js';
import {
  busyText, describeText, errorsCsv, shimmerStoppedText, statusText, summaryText,
} from '../../src/panels/normal-mips/words.js';
import { schema } from '../../src/panels/normal-mips/schema.js';

const defaults = () => Object.fromEntries(Object.entries(schema).map(([key, spec]) => [key, spec.default]));
const flush = () => new Promise((resolve) => { setTimeout(resolve, 0); });

/** A chain builder whose builds resolve when the test says so. */
function stubBuilder() {
  const builds = [];
  return {
    workers: 2,
    problem: null,
    disposed: false,
    builds,
    build(request) {
      return new Promise((resolve, reject) => { builds.push({ request, resolve, reject }); });
    },
    dispose() { this.disposed = true; },
  };
}

/** The GPU scene as the runs sees it: calls recorded, shimmer measurements resolved by the test. */
function stubScene() {
  const scene = {
    maxAnisotropy: 4,
    floatLinear: true,
    state: { samples: 0, cap: 128, errors: null },
    chains: [],
    sets: [],
    refreshes: 0,
    shimmers: [],
    setChains(chains) { scene.chains.push(chains); },
    set(settings, truthChanged) { scene.sets.push({ settings, truthChanged }); },
    refreshErrors() { scene.refreshes += 1; },
    measureShimmer({ signal }) {
      return new Promise((resolve, reject) => {
        scene.shimmers.push({ signal, resolve });
        if (signal.aborted) reject(signal.reason);
        signal.addEventListener('abort', () => reject(signal.reason));
      });
    },
  };
  return scene;
}

const built = (tag) => ({ chains: { tag }, pyramid: { tag }, uploads: {}, ms: 41.6, where: '2 workers', workers: 2 });

function setup({ withScene = true, values = defaults() } = {}) {
  const builder = stubBuilder();
  const scene = withScene ? stubScene() : null;
  const events = [];
  const hooks = {
    applied: (keys) => events.push(['applied', keys]),
    busy: (text) => events.push(['busy', text]),
    summary: () => events.push(['summary']),
    shimmer: () => events.push(['shimmer']),
    invalidate: () => events.push(['invalidate']),
  };
  const runs = createNormalMipsRuns({ values, builder, scene, hooks });
  return { runs, builder, scene, events, values };
}

/** A runs whose first chains have arrived. */
async function ready(options) {
  const parts = setup(options);
  parts.runs.update();
  parts.builder.builds[0].resolve(built('first'));
  await parts.runs.whenBuilt();
  parts.events.length = 0;
  if (parts.scene) parts.scene.sets.length = 0;
  return parts;
}

describe('normal-mips runs: chain builds', () => {
  it('builds the chains of the values at mount, says so, then applies everything and tells the scene', async () => {
    const { runs, builder, scene, events, values } = setup();
    runs.update();
    expect(builder.builds).toHaveLength(1);
    expect(builder.builds[0].request).toEqual({
      kind: 'bumps', params: { frequency: 16, edgeAngleDeg: 35 }, size: 256, precision: 'f16', channels: 3,
    });
    expect(events).toEqual([['busy', { size: 256 }], ['summary']]);
    expect(runs.building).toBe(true);
    builder.builds[0].resolve(built('first'));
    await runs.whenBuilt();
    expect(runs.chains).toEqual({ tag: 'first' });
    expect(runs.built).toEqual({ ms: 41.6, workers: 2, size: 256 });
    expect(runs.building).toBe(false);
    expect(scene.chains).toEqual([{ tag: 'first' }]);
    expect(scene.sets).toHaveLength(1);
    expect(scene.sets[0].truthChanged).toBe(true);
    expect(scene.sets[0].settings).toEqual(sceneSettings(values, { levels: 9, anisotropy: 1 }));
    expect(events.slice(2)).toEqual([['busy', null], ['applied', null], ['invalidate']]);
  });

  it('holds other changes until the newest chains arrive, then applies them together', async () => {
    const { runs, builder, scene, events, values } = await ready();
    values.size = '128';
    runs.update(['size']);
    values.technique = 'lean';
    runs.update(['technique']);
    expect(scene.sets).toHaveLength(0); // the old picture stays while the chains build
    expect(events).toEqual([['busy', { size: 128 }]]); // chains are there: no summary
    builder.builds[1].resolve(built('second'));
    await runs.whenBuilt();
    expect(events.at(-2)).toEqual(['applied', ['size', 'technique']]);
    expect(scene.sets).toHaveLength(1);
    expect(scene.sets[0].truthChanged).toBe(false); // neither size nor technique changes the truth
    expect(scene.sets[0].settings.technique).toBe('lean');
    expect(scene.sets[0].settings.uMaxLevel).toBe(7);
    expect(scene.refreshes).toBe(1); // a new size changes what the techniques store: errors measured again
  });

  it('drops a build that a newer one made stale, even if it arrives last', async () => {
    const { runs, builder, scene, values } = await ready();
    values.size = '64';
    runs.update(['size']);
    values.size = '512';
    runs.update(['size']);
    builder.builds[2].resolve(built('newest'));
    await flush();
    builder.builds[1].resolve(built('stale'));
    await runs.whenBuilt();
    expect(runs.chains).toEqual({ tag: 'newest' });
    expect(runs.built.size).toBe(512);
    expect(scene.chains.map((c) => c.tag)).toEqual(['first', 'newest']);
  });

  it('applies a change that needs no chains at once, and re-describes on []', async () => {
    const { runs, builder, scene, events } = await ready();
    runs.update(['lightEl']);
    expect(scene.sets.at(-1).truthChanged).toBe(true);
    runs.update(['level']);
    expect(scene.sets.at(-1).truthChanged).toBe(false);
    expect(scene.refreshes).toBe(1);
    runs.update([]);
    expect(scene.sets).toHaveLength(2); // nothing to draw
    expect(events.at(-1)).toEqual(['applied', []]);
    expect(builder.builds).toHaveLength(1);
  });

  it('tells the view why a build failed', async () => {
    const { runs, builder, events, values } = await ready();
    values.size = '64';
    runs.update(['size']);
    const refusal = new RangeError('size 64 refused');
    builder.builds[1].reject(refusal);
    await runs.whenBuilt();
    expect(events.at(-1)).toEqual(['busy', { error: refusal }]);
    expect(runs.building).toBe(false);
  });

  it('asks the scene for no more than the GPU offers', async () => {
    const { runs, scene, values } = await ready();
    values.anisotropy = '16';
    runs.update(['anisotropy']);
    expect(scene.sets.at(-1).settings.anisotropy).toBe(4);
    expect(runs.anisotropyInUse()).toBe(4);
  });
});

describe('normal-mips runs: the shimmer meter', () => {
  it('measures, shows the numbers and re-describes', async () => {
    const { runs, scene, events } = await ready();
    const done = runs.measureShimmer();
    await flush();
    expect(runs.shimmer.busy).toBe(true);
    expect(events).toEqual([['shimmer']]);
    scene.shimmers[0].resolve({ toksvig: 0.01 });
    await done;
    expect(runs.shimmer).toEqual({ result: { toksvig: 0.01 }, busy: false, stopped: '' });
    expect(events.slice(1)).toEqual([['shimmer'], ['invalidate']]);
  });

  it('drops a measurement that a newer one made stale', async () => {
    const { runs, scene } = await ready();
    const first = runs.measureShimmer();
    await flush();
    const second = runs.measureShimmer();
    await flush();
    expect(scene.shimmers[0].signal.aborted).toBe(true);
    expect(scene.shimmers[1].signal.aborted).toBe(false);
    await first; // the stale one ends without a word
    expect(runs.shimmer.busy).toBe(true);
    scene.shimmers[1].resolve({ toksvig: 0.02 });
    await second;
    expect(runs.shimmer.result).toEqual({ toksvig: 0.02 });
  });

  it('forgets the numbers and drops a running measurement when what it measures changes, not otherwise', async () => {
    const { runs, scene } = await ready();
    const done = runs.measureShimmer();
    await flush();
    scene.shimmers[0].resolve({ toksvig: 0.01 });
    await done;
    runs.update(['technique']); // the meter measures every technique: still valid
    expect(runs.shimmer.result).toEqual({ toksvig: 0.01 });
    const running = runs.measureShimmer();
    await flush();
    runs.update(['viewEl']);
    expect(scene.shimmers[1].signal.aborted).toBe(true);
    expect(runs.shimmer).toEqual({ result: null, busy: false, stopped: '' });
    await running;
    expect(runs.shimmer.result).toBeNull();
  });

  it('stops on a lost context and says so; a null from the scene says the same', async () => {
    const { runs, scene, events } = await ready();
    const done = runs.measureShimmer();
    await flush();
    runs.contextLost();
    expect(scene.shimmers[0].signal.aborted).toBe(true);
    expect(runs.shimmer).toEqual({ result: null, busy: false, stopped: 'lost' });
    expect(events.slice(-2)).toEqual([['shimmer'], ['invalidate']]);
    await done;
    expect(runs.shimmer.stopped).toBe('lost');
    const again = runs.measureShimmer();
    await flush();
    expect(runs.shimmer.stopped).toBe('');
    scene.shimmers[1].resolve(null); // the context went away under a read-back before its event
    await again;
    expect(runs.shimmer).toEqual({ result: null, busy: false, stopped: 'lost' });
  });

  it('a lost context while nothing is measured changes nothing', async () => {
    const { runs, events } = await ready();
    runs.contextLost();
    expect(events).toEqual([]);
    expect(runs.shimmer.stopped).toBe('');
  });

  it('without a scene there are no numbers and no complaint', async () => {
    const { runs } = await ready({ withScene: false });
    await runs.measureShimmer();
    expect(runs.shimmer).toEqual({ result: null, busy: false, stopped: '' });
  });
});

describe('normal-mips runs: dispose', () => {
  it('stops the builder, drops a build and a measurement under way, and calls no hook after', async () => {
    const { runs, builder, scene, events, values } = await ready();
    values.size = '64';
    runs.update(['size']);
    const measuring = runs.measureShimmer(); // waits for the build
    runs.dispose();
    expect(builder.disposed).toBe(true);
    events.length = 0;
    builder.builds[1].resolve(built('late'));
    await measuring;
    expect(scene.chains.map((c) => c.tag)).toEqual(['first']);
    expect(scene.shimmers).toHaveLength(0); // the measurement never started on a panel that is gone
    expect(events).toEqual([]);
    expect(runs.shimmer.result).toBeNull();
  });
});

describe('normal-mips runs: dispose of a running measurement', () => {
  it('aborts it and keeps its late numbers out', async () => {
    const { runs, scene, events } = await ready();
    const running = runs.measureShimmer();
    await flush();
    runs.dispose();
    expect(scene.shimmers[0].signal.aborted).toBe(true);
    events.length = 0;
    await running;
    expect(events).toEqual([]);
    expect(runs.shimmer.result).toBeNull();
  });
});

describe('normal-mips settings', () => {
  it('puts the light ahead of the view centre at azimuth 0, to the left for negative azimuths', () => {
    const ahead = lightPlacement({ viewEl: 45, lightEl: 0, lightAz: 0, lightDist: 2 });
    expect(ahead.position[0]).toBeCloseTo(0, 12);
    expect(ahead.position[2]).toBeCloseTo(1 + 2, 12); // the view centre at 1/tan 45° = 1, then 2 tiles ahead
    expect(Math.hypot(...ahead.fromCamera)).toBeCloseTo(1, 12);
    expect(lightPlacement({ viewEl: 45, lightEl: 0, lightAz: -30, lightDist: 2 }).position[0]).toBeCloseTo(-1, 12);
  });

  it('gives the checker an even feature count and the mixed map its blocks', () => {
    expect(mapParams({ map: 'checker', frequency: 6, angle: 20 })).toEqual({ frequency: 6, angleDeg: 20 });
    expect(mapParams({ map: 'checker', frequency: 2, angle: 20 }).frequency).toBe(2);
    expect(mapParams({ map: 'mixed', frequency: 16, angle: 20 })).toMatchObject({ blocks: 4, frequency: 2 });
    expect(chainRequest({ ...defaults(), size: '64', channels: '2' })).toMatchObject({ size: 64, channels: 2 });
  });

  it('merges waiting keys: null (all) wins', () => {
    expect(mergeKeys(undefined, ['a'])).toEqual(['a']);
    expect(mergeKeys(undefined, undefined)).toBeNull();
    expect(mergeKeys(['a'], ['b'])).toEqual(['a', 'b']);
    expect(mergeKeys(null, ['b'])).toBeNull();
    expect(mergeKeys(['a'], null)).toBeNull();
  });

  it('forces no level beyond the chain, and shows the technique alone with the truth off', () => {
    const values = { ...defaults(), level: 10, truth: false, view: 'truth' };
    const settings = sceneSettings(values, { levels: 9, anisotropy: 1 });
    expect(settings.uForcedLevel).toBe(8);
    expect(settings.uView).toBe(1);
    expect(sceneSettings({ ...values, truth: true }, { levels: 9, anisotropy: 1 }).uView).toBe(2);
  });
});

describe('normal-mips words', () => {
  const facts = { built: { ms: 41.6, workers: 2, size: 256 }, maxAnisotropy: 4, floatLinear: false, problem: '' };

  it('writes the line of key numbers', () => {
    // s = 2/α² − 2 = 48 at α = 0.2; R0 = ((1.5 − 1)/(1.5 + 1))² = 0.04
    expect(summaryText(defaults(), facts)).toBe('Toksvig, 16-bit float, 3 channels; base Beckmann α = 0.2 (Blinn-Phong s = 48.0); '
      + 'mip level automatic, trilinear of 0–8; R0 = 0.040; all six chains of the 256² map built in 42 ms (2 workers).');
    const line = summaryText({ ...defaults(), anisotropy: '16', precision: 'f32' }, { ...facts, built: { ms: 0, workers: 0, size: 0 } });
    expect(line).toContain('4× anisotropic filtering (this GPU offers at most 4×)');
    expect(line).toContain('the six chains of the 256² map are being built.');
    expect(line).toContain('This GPU cannot filter 32-bit float textures');
    const forced = summaryText({ ...defaults(), level: 3 }, { ...facts, problem: 'No workers.' });
    expect(forced).toMatch(/forced to 3 of 0–8; .* No workers\.$/);
  });

  it('says what the chain build is doing and why a shimmer measurement stopped', () => {
    expect(busyText({ size: 256 })).toBe('Building the mip chains of a 256² map…');
    expect(busyText({ error: new RangeError('size 64 refused') })).toBe('Could not build the mip chains: size 64 refused');
    expect(busyText(null)).toBe('');
    expect(shimmerStoppedText('lost')).toBe('Shimmer meter: the measurement stopped because the graphics context was lost; '
      + 'press “Measure shimmer” again once the picture is back.');
    expect(shimmerStoppedText('')).toBe('');
  });

  it('captions the picture and says why there are no numbers yet', () => {
    expect(statusText(defaults(), { samples: 64, cap: 128 })).toEqual({
      left: 'Toksvig', right: 'ground truth, 64 samples/pixel', pending: 'Ground truth converging: 64 of 128 samples per pixel…',
    });
    expect(statusText({ ...defaults(), view: 'difference' }, { samples: 128, cap: 128 })).toEqual({
      left: '|Toksvig − truth|',
      right: 'ground truth, 128 samples/pixel',
      pending: 'Ground truth converged: measuring each technique against it…',
    });
    expect(statusText({ ...defaults(), truth: false }, { samples: 0, cap: 128 }).pending).toMatch(/^Ground truth off/);
  });

  it('describes the errors best and worst with four decimals, and writes them as CSV', () => {
    const bands = [{ level: 0, rmse: 0.1 }, { level: 1, rmse: 0.2 }];
    const errors = {
      naive: { rmse: 0.08, bands }, renormalized: { rmse: 0.06, bands }, toksvig: { rmse: 0.012345, bands },
      lean: { rmse: 0.02, bands }, clean: { rmse: 0.03, bands }, vmf: { rmse: 0.011, bands },
    };
    const text = describeText(defaults(), { errors, shimmer: { toksvig: 0.00049 }, plotNote: 'Note.' });
    expect(text).toBe('Toksvig on bumps at base α = 0.2, using the automatic mip level: RMSE against the ground truth 0.0123; '
      + 'best vMF (0.0110), worst Naive average (0.0800). Note. Shimmer of Toksvig: 0.0005 mean brightness change per pixel.');
    expect(describeText({ ...defaults(), truth: false }, { errors, shimmer: null, plotNote: '' })).toMatch(/ground truth is off/);
    const csv = errorsCsv(defaults(), errors);
    expect(csv.filename).toBe('normal-mips-bumps-errors.csv');
    expect(csv.columns.rmse_level_1).toEqual([0.2, 0.2, 0.2, 0.2, 0.2, 0.2]);
    expect(errorsCsv(defaults(), null).columns).toEqual({ technique: [] });
  });
});
