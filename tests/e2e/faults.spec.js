// Each fault a lecture hall meets, injected, and survived with a message: a lost and restored
// WebGL context in every WebGL panel, a chain-building worker that cannot start or fails, a GPU
// that refuses the shaders, and an error in a panel's own code (the other panels go on).
import { test, expect, openLab, settledFrames, hostFrames } from './fixtures.js';
import { PANELS } from '../../src/panels/manifest.js';

const WEBGL = PANELS.filter((p) => p.webgl).map((p) => p.id);
const LOST_LINE = /The graphics context was lost; restoring it/;

/** Every WebGL context of panel `id`: its canvases' and a detached one it exposes as `gl`. */
const contextsOf = (id) => {
  const host = window.fresnelLab.hosts[id];
  const found = [...host.container.querySelectorAll('canvas')].map((c) => c.getContext('webgl2')).filter(Boolean);
  const own = window.fresnelLab.panels[id]?.gl;
  if (own && !found.includes(own)) found.push(own);
  return found;
};

test.describe('a lost context', () => {
  for (const id of WEBGL) {
    test(`${id}: said while it is gone, redrawn when it is back`, async ({ page }) => {
      await openLab(page, `embed.html?panel=${id}&reducedMotion=1`); // still, so that its frames can be counted
      await settledFrames(page, id);
      const count = await page.evaluate(`(${contextsOf})(${JSON.stringify(id)}).length`);
      expect(count, 'the panel has a WebGL context').toBeGreaterThan(0);
      await page.evaluate(`(async () => {
        const contexts = (${contextsOf})(${JSON.stringify(id)});
        window.lost = contexts.map((gl) => gl.getExtension('WEBGL_lose_context'));
        await Promise.all(contexts.map((gl) => new Promise((resolve) => {
          gl.canvas.addEventListener('webglcontextlost', resolve, { once: true });
        })).concat(window.lost.map((ext) => void ext.loseContext())));
      })()`);
      const line = page.locator('.panel-fault-text');
      await expect(line).toHaveText(LOST_LINE);
      await expect(line).toBeVisible();
      const frames = await hostFrames(page, id);
      await page.evaluate(() => window.lost.forEach((ext) => ext.restoreContext()));
      await expect(page.locator('.panel-fault')).toBeHidden();
      if (id === 'stability') {
        // Its maps are 2D pictures of values already read back, which the loss did not touch; a
        // new map is evaluated on the restored context.
        await page.evaluate(() => window.fresnelLab.hosts.stability.set({ method: 'schlick-pow' }));
      }
      // Drawn again by itself: the restored context's textures, targets and programs are made anew.
      await expect.poll(() => hostFrames(page, id), { message: `${id} drew after the restore` }).toBeGreaterThan(frames);
      if (id === 'stability') expect(await page.evaluate(() => window.fresnelLab.panels.stability.maps.gpu)).not.toBeNull();
      expect(await page.evaluate((panelId) => window.fresnelLab.hosts[panelId].faults, id)).toEqual({ errors: 0, lost: 0 });
    });
  }

  test('normal-mips: a shimmer measurement cut by the loss says it stopped, and nothing is left unhandled', async ({ page }) => {
    await openLab(page, 'embed.html?panel=normal-mips&truth=false');
    await page.evaluate(() => window.fresnelLab.panels['normal-mips'].whenBuilt());
    await page.getByText('Measure shimmer (all techniques)').click();
    await expect(page.locator('.nm-shimmer')).toHaveText(/measuring every technique/);
    await page.evaluate(() => {
      window.lost = window.fresnelLab.panels['normal-mips'].scene.gl.getExtension('WEBGL_lose_context');
      window.lost.loseContext();
    });
    await expect(page.locator('.panel-fault-text')).toHaveText(LOST_LINE);
    await page.evaluate(() => window.lost.restoreContext());
    await expect(page.locator('.nm-shimmer')).toHaveText(/the measurement stopped because the graphics context was lost/);
    await expect(page.locator('.panel-fault')).toBeHidden();
    // Measured again on the restored context: numbers, not a message.
    await page.getByText('Measure shimmer (all techniques)').click();
    await expect(page.locator('.nm-shimmer')).toHaveText(/^Shimmer \(mean brightness change/, { timeout: 60_000 });
  });
});

test.describe('a loss in the middle of progressive work', () => {
  test('normal-mips: lost while the ground truth accumulates, said, and accumulated to its cap once back', async ({ page }) => {
    await openLab(page, 'embed.html?panel=normal-mips'); // the truth on, as the panel starts
    // Lost in the same task that sees the truth started but not finished.
    const at = await (await page.waitForFunction(() => {
      const { state, gl } = window.fresnelLab.panels['normal-mips'].scene ?? {};
      if (!(state?.samples > 0 && state.samples < state.cap)) return false;
      window.lost = gl.getExtension('WEBGL_lose_context');
      window.lost.loseContext();
      return { samples: state.samples, cap: state.cap };
    }, null, { timeout: 60_000 })).jsonValue();
    expect(at.samples).toBeLessThan(at.cap);
    await expect(page.locator('.panel-fault-text')).toHaveText(LOST_LINE);
    await expect(page.locator('.nm-errors')).toContainText('Ground truth converging');
    await page.evaluate(() => window.lost.restoreContext());
    await expect(page.locator('.panel-fault')).toBeHidden();
    // Started over on the restored context and accumulated to its cap, then measured.
    await expect.poll(() => page.evaluate(() => window.fresnelLab.panels['normal-mips'].scene.state.samples), { timeout: 60_000 })
      .toBeGreaterThanOrEqual(at.cap);
    await expect.poll(() => page.evaluate(() => Boolean(window.fresnelLab.panels['normal-mips'].scene.state.errors)), { timeout: 60_000 })
      .toBe(true);
    expect(await page.evaluate(() => window.fresnelLab.hosts['normal-mips'].faults)).toEqual({ errors: 0, lost: 0 });
  });

  test('normal-mips: every canvas asked for WebGL before the chains arrive (the loss tests do), and its 2D pictures still draw', async ({ page }) => {
    // The chain workers' answers are held back until the contexts are lost, so the loss always comes
    // before the chains (racing the workers, it came after them on a fast load).
    await page.addInitScript(() => {
      const held = [];
      let holding = true;
      window.releaseChainWorkers = () => { holding = false; held.splice(0).forEach((deliver) => deliver()); };
      const NativeWorker = window.Worker;
      window.Worker = class extends NativeWorker {
        constructor(url, options) {
          super(url, options);
          if (!String(url).includes('chainWorker')) return;
          // Registered before the page's own listeners, so it sees each answer first.
          this.addEventListener('message', (event) => {
            if (!holding) return;
            event.stopImmediatePropagation();
            held.push(() => this.dispatchEvent(new MessageEvent('message', { data: event.data })));
          });
        }
      };
    });
    await openLab(page, 'embed.html?panel=normal-mips');
    // Before the worker's chains: the strip and inspector canvases have no picture yet.
    const early = await page.evaluate(`(() => {
      const early = !window.fresnelLab.panels['normal-mips'].chains;
      window.lost = (${contextsOf})('normal-mips').map((gl) => gl.getExtension('WEBGL_lose_context'));
      window.lost.forEach((ext) => ext.loseContext());
      return early;
    })()`);
    expect(early, 'the chains were still being built').toBe(true);
    await page.evaluate(() => window.releaseChainWorkers());
    await page.evaluate(() => window.fresnelLab.panels['normal-mips'].whenBuilt());
    await page.evaluate(() => window.lost.forEach((ext) => ext.restoreContext()));
    await expect(page.locator('.panel-fault')).toBeHidden();
    expect(await page.evaluate(() => window.fresnelLab.panels['normal-mips'].inspected?.points.length)).toBeGreaterThan(0);
    await expect.poll(() => page.evaluate(() => window.fresnelLab.panels['normal-mips'].scene.state.samples), { timeout: 60_000 })
      .toBeGreaterThan(0);
  });
});

test.describe('a chain-building worker', () => {
  test('that cannot start: the chains are built on the page’s thread, and the panel says so', async ({ page }) => {
    await page.addInitScript(() => {
      window.Worker = class { constructor() { throw new Error('workers are blocked here'); } };
    });
    await openLab(page, 'embed.html?panel=normal-mips&truth=false');
    await page.evaluate(() => window.fresnelLab.panels['normal-mips'].whenBuilt());
    await expect(page.locator('.nm-summary')).toContainText('built in');
    await expect(page.locator('.nm-summary')).toContainText('(main thread)');
    await expect(page.locator('.nm-summary')).toContainText('The chain-building workers could not start (workers are blocked here)');
  });

  test('that fails once started: the build falls back and the panel says so', async ({ page }) => {
    await page.addInitScript(() => {
      window.Worker = class {
        postMessage() {
          setTimeout(() => this.onerror?.({ message: 'the worker’s script failed', preventDefault() {} }), 0);
        }
        terminate() {}
      };
    });
    await openLab(page, 'embed.html?panel=normal-mips&truth=false');
    await page.evaluate(() => window.fresnelLab.panels['normal-mips'].whenBuilt());
    await expect(page.locator('.nm-summary')).toContainText('(main thread)');
    await expect(page.locator('.nm-summary')).toContainText('A chain-building worker failed (the worker’s script failed)');
    expect(await page.evaluate(() => window.fresnelLab.panels['normal-mips'].chains.naive.size)).toBe(256);
  });
});

test.describe('a GPU that refuses every shader', () => {
  test.use({ allowedErrors: /did not compile|could not compile|shader compile failed|injected refusal/i });
  test.beforeEach(async ({ page }) => {
    await page.addInitScript(() => {
      const proto = WebGL2RenderingContext.prototype;
      const parameter = proto.getShaderParameter;
      proto.getShaderParameter = function (shader, name) {
        return name === this.COMPILE_STATUS ? false : parameter.call(this, shader, name);
      };
      proto.getShaderInfoLog = () => "ERROR: 0:1: 'injected refusal' : this driver refuses the shader";
    });
  });

  test('the lecture page: each WebGL panel says why it has no picture, and the rest works', async ({ page }) => {
    await openLab(page, './');
    for (const id of WEBGL) {
      const section = page.locator(`section[data-panel="${id}"]`);
      await section.scrollIntoViewIfNeeded();
      await expect.poll(() => page.evaluate((panelId) => window.fresnelLab.hosts[panelId].mounted, id), { message: `${id} mounted` }).toBe(true);
      await expect(section.getByText(/could not compile|injected refusal/).first(), `${id} says what the GPU refused`).toBeVisible();
    }
    // Panels without WebGL are untouched: the exact-Fresnel plot still follows its index.
    const exact = page.locator('section[data-panel="exact-fresnel"]');
    await exact.scrollIntoViewIfNeeded();
    await expect.poll(() => page.evaluate(() => window.fresnelLab.hosts['exact-fresnel'].mounted)).toBe(true);
    const before = await page.evaluate(() => window.fresnelLab.hosts['exact-fresnel'].instance.describe());
    await page.evaluate(() => window.fresnelLab.hosts['exact-fresnel'].set({ nT: 2.4 }));
    await expect.poll(() => page.evaluate(() => window.fresnelLab.hosts['exact-fresnel'].instance.describe())).not.toBe(before);
    await expect(page.locator('.notice-error')).toHaveCount(0); // no panel failed to start
  });
});

/** A panel still answers its controls: a new value changes what it says about itself. */
async function expectFollowsControls(page, id) {
  const describe = () => page.evaluate((i) => window.fresnelLab.hosts[i].instance.describe(), id);
  const before = await describe();
  await page.evaluate((i) => window.fresnelLab.hosts[i].set({ nT: 2.4 }), id);
  await expect.poll(describe).not.toBe(before);
}

test.describe('an error in a panel’s code', () => {
  test.use({ allowedErrors: /met an error|an injected fault/ });

  test('an update that throws: a notice in that panel, a restart that works, the others unaffected', async ({ page }) => {
    await openLab(page, './#spheres');
    await page.evaluate(() => {
      const panel = window.fresnelLab.panels.spheres;
      const update = panel.update;
      panel.update = () => { throw new Error('an injected fault in update'); };
      window.restore = () => { panel.update = update; };
    });
    await page.evaluate(() => window.fresnelLab.hosts.spheres.set({ nT: 2 }));
    const spheres = page.locator('section[data-panel="spheres"]');
    await expect(spheres.locator('.panel-fault-text')).toHaveText(/The .* panel met an error: an injected fault in update\. The other panels are not affected\./);
    await expect(page.locator('.panel-fault:visible')).toHaveCount(1);
    // The next panel on the page still follows its controls.
    const exact = page.locator('section[data-panel="exact-fresnel"]');
    await exact.scrollIntoViewIfNeeded();
    await expect.poll(() => page.evaluate(() => window.fresnelLab.hosts['exact-fresnel'].mounted)).toBe(true);
    await expectFollowsControls(page, 'exact-fresnel');
    // Restart: a new instance with the values the panel had, and the line gone.
    await spheres.scrollIntoViewIfNeeded();
    await spheres.getByRole('button', { name: 'Restart this panel' }).click();
    await expect(spheres.locator('.panel-fault')).toBeHidden();
    expect(await page.evaluate(() => window.fresnelLab.hosts.spheres.values.nT)).toBe(2);
    const frames = await hostFrames(page, 'spheres');
    await page.evaluate(() => window.fresnelLab.hosts.spheres.set({ nT: 1.8 }));
    await expect.poll(() => hostFrames(page, 'spheres')).toBeGreaterThan(frames);
    await expect(spheres.locator('.panel-fault')).toBeHidden();
  });

  test('a listener that throws on a key press: said in its panel, and the page goes on', async ({ page }) => {
    await openLab(page, 'embed.html?panel=exact-fresnel');
    await page.evaluate(() => {
      const canvas = document.querySelector('canvas');
      canvas.tabIndex = 0;
      canvas.addEventListener('keydown', () => { throw new Error('an injected fault in a key handler'); });
    });
    await page.locator('canvas').first().focus();
    await page.keyboard.press('ArrowRight');
    await expect(page.locator('.panel-fault-text')).toHaveText(/met an error: an injected fault in a key handler/);
    await expectFollowsControls(page, 'exact-fresnel');
  });

  test('an error outside every panel: one notice at the top of the page', async ({ page }) => {
    await openLab(page, './');
    await page.evaluate(() => { setTimeout(() => { throw new Error('an injected fault on the page'); }, 0); });
    await expect(page.locator('main > .notice-error')).toContainText('Something went wrong on this page:');
    await expect(page.locator('main > .notice-error')).toContainText('an injected fault on the page');
  });
});
