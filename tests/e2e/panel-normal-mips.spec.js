import { test, expect, openLab, expectIdle } from './fixtures.js';
import { openInPseudoLocale, panelWordsOutside } from './wordsOutside.js';

const PANEL = 'normal-mips';
const URL = `./embed.html?panel=${PANEL}`;

test.use({ viewport: { width: 900, height: 700 } });

test('mounts in an embed and honours the URL', async ({ page }) => {
  await openLab(page, `${URL}&technique=lean&map=grooves&precision=u8&channels=2&level=3&truth=false`);
  await expect(page.locator('.nm-canvas')).toHaveAttribute('aria-label', /receding/);
  const summary = page.locator('.nm-summary');
  await expect(summary).toContainText('LEAN, 8-bit unorm, 2 channels');
  await expect(summary).toContainText('forced to 3 of 0–8');
  const state = await page.evaluate(async (id) => {
    const p = window.fresnelLab.panels[id];
    await p.whenBuilt();
    return { technique: p.scene.state.technique, level: p.scene.uniforms.uForcedLevel.value, kind: p.scene.uniforms.uMapKind.value, precision: p.chains.lean.precision };
  }, PANEL);
  expect(state).toEqual({ technique: 'lean', level: 3, kind: 1, precision: 'u8' });
});

test('every uploaded mip level is sampled exactly with textureLod', async ({ page }) => {
  await openLab(page, `${URL}&truth=false`);
  const cases = [['toksvig', 'f16', '3'], ['lean', 'u8', '3'], ['vmf', 'f32', '2'], ['renormalized', 'u8', '2']];
  for (const [technique, precision, channels] of cases) {
    const worst = await page.evaluate(async ([id, t, p, c]) => {
      window.fresnelLab.hosts[id].set({ precision: p, channels: c });
      const panel = window.fresnelLab.panels[id];
      await panel.whenBuilt(); // the chains are built in a worker
      const chain = panel.chains[t];
      let max = 0;
      chain.textures.forEach(({ sources }, k) => {
        for (const { level, size, data } of chain.levels) {
          const probe = panel.scene.debugLevel(t, level, k);
          for (let y = 0; y < Math.min(probe.height, 64); y++) {
            for (let x = 0; x < Math.min(probe.width, 64); x++) {
              const texel = (y % size) * size + (x % size);
              sources.forEach((s, comp) => {
                const expected = typeof s === 'number' ? data[texel * chain.components + s] : s.pad;
                const got = probe.data[(y * probe.width + x) * 4 + comp];
                max = Math.max(max, Math.abs(got - expected));
              });
            }
          }
        }
      });
      return max;
    }, [PANEL, technique, precision, channels]);
    // Float data comes back bit for bit; 8-bit codes decode within float32 rounding of min + (max − min)·c/255.
    expect(worst, `${technique} ${precision} ${channels}`).toBeLessThan(precision === 'u8' ? 2e-6 : 1e-7);
  }
});

test('far bumps: variance-keeping techniques beat renormalized and naive, and the table agrees', async ({ page }) => {
  test.setTimeout(60_000);
  await openLab(page, `${URL}&map=bumps&truthSamples=32`);
  await page.waitForFunction((id) => window.fresnelLab.panels[id]?.scene.state.errors, PANEL, { timeout: 45_000 });
  const errors = await page.evaluate((id) => window.fresnelLab.panels[id].scene.state.errors, PANEL);
  // At the default base roughness (α = 0.2) the order holds in every band up to λ 7 (at λ 8 the
  // whole map is one texel, where all techniques nearly agree).
  for (const good of ['toksvig', 'clean', 'lean', 'vmf']) {
    for (const bad of ['renormalized', 'naive']) {
      expect(errors[good].rmse, `${good} < ${bad}`).toBeLessThan(errors[bad].rmse);
      for (const band of errors[good].bands.filter((b) => b.count > 0 && b.level <= 7)) {
        expect(band.rmse, `${good} < ${bad} at λ ${band.level}`).toBeLessThan(errors[bad].bands[band.level].rmse);
      }
    }
  }
  await expect(page.locator('.nm-plot-note')).toHaveText(/Toksvig is closer to the truth than the naive average at every mip level/);
  const plotted = await page.evaluate((id) => window.fresnelLab.panels[id].distancePlot.data, PANEL);
  expect(plotted[3]).toEqual(plotted[0].map((level) => errors.toksvig.bands[level].rmse)); // series 3: toksvig
  // The table lists techniques best first, with the same numbers.
  const rows = await page.locator('.nm-errors tbody tr').evaluateAll((trs) => trs.map((tr) => [tr.dataset.technique, Number(tr.children[1].textContent)]));
  expect(rows.slice(4).map((r) => r[0]).sort()).toEqual(['naive', 'renormalized']);
  for (const [technique, value] of rows) expect(value).toBeCloseTo(errors[technique].rmse, 4);
  await expect(page.locator('.panel-description')).toContainText(`RMSE against the ground truth ${errors.toksvig.rmse.toFixed(4)}`);
  await expect(page.locator('.panel-description')).toContainText('Toksvig is closer to the truth than the naive average at every mip level');
  const csv = await page.evaluate((id) => window.fresnelLab.panels[id].csv(), PANEL);
  expect(csv.columns.technique).toEqual(['naive', 'renormalized', 'toksvig', 'lean', 'clean', 'vmf']);
  expect(csv.columns.rmse[2]).toBe(errors.toksvig.rmse);
  // Two stored channels rebuild z, so |N| = 1 and Toksvig sees no variance: it falls back to renormalized
  // (re-measured against the same converged truth, which is not restarted).
  const twoChannel = await page.evaluate(async (id) => {
    window.fresnelLab.hosts[id].set({ channels: '2' });
    await window.fresnelLab.panels[id].whenBuilt();
    await window.fresnelLab.panels[id].scene.whenMeasured(); // one technique per frame
    const { state } = window.fresnelLab.panels[id].scene;
    return { samples: state.samples, toksvig: state.errors.toksvig.rmse, renormalized: state.errors.renormalized.rmse, lean: state.errors.lean.rmse };
  }, PANEL);
  expect(twoChannel.samples).toBe(32);
  expect(Math.abs(twoChannel.toksvig - twoChannel.renormalized)).toBeLessThan(0.05 * twoChannel.renormalized);
  expect(twoChannel.lean).toBeCloseTo(errors.lean.rmse, 6); // LEAN stores slopes, not normals
  // Rendering stops once the truth has converged and the errors are measured.
  await expectIdle(page, PANEL, 24);
});

test('controls change the picture', async ({ page }) => {
  await openLab(page, `${URL}&truth=false&view=technique`);
  const sum = (id, values) => page.evaluate(async ([pid, v]) => {
    window.fresnelLab.hosts[pid].set(v);
    await window.fresnelLab.panels[pid].whenBuilt();
    const url = window.fresnelLab.panels[pid].scene.toDataURL();
    return url.length;
  }, [id, values]);
  const plain = await sum(PANEL, { overlay: false });
  const overlay = await sum(PANEL, { overlay: true });
  expect(overlay).not.toBe(plain);
  const pixel = (values) => page.evaluate(async ([pid, v]) => {
    window.fresnelLab.hosts[pid].set(v);
    await window.fresnelLab.panels[pid].whenBuilt();
    const image = window.fresnelLab.panels[pid].scene.readTechnique();
    let total = 0;
    for (let o = 0; o < image.length; o += 4) if (image[o + 3] >= 0) total += image[o] + image[o + 1] + image[o + 2];
    return total;
  }, [PANEL, values]);
  const naive = await pixel({ overlay: false, technique: 'naive' });
  const toksvig = await pixel({ technique: 'toksvig' });
  expect(Math.abs(naive - toksvig) / naive).toBeGreaterThan(0.02);
});

test('mip strip and texel inspector: V-grooves average to cos θ, one blob for two spikes', async ({ page }) => {
  await openLab(page, `${URL}&truth=false&map=grooves&angle=30&frequency=16&texelLevel=4`);
  await expect(page.locator('.nm-strip-cell')).toHaveCount(27); // 9 levels × RGB, |N_a|, α′
  const { meanLength, inspected } = await page.evaluate(async (id) => {
    const p = window.fresnelLab.panels[id];
    await p.whenBuilt();
    return { meanLength: p.stripStats.meanLength, inspected: p.inspected };
  }, PANEL);
  // Period 16 texels: levels ≥ 4 average both facets to |N_a| = cos 30° (f16 storage).
  expect(meanLength[0]).toBeCloseTo(1, 3);
  expect(meanLength[5]).toBeCloseTo(Math.cos(Math.PI / 6), 3);
  const xs = inspected.points.map((p) => p[0]);
  expect(Math.min(...xs)).toBeCloseTo(-Math.tan(Math.PI / 6), 3);
  expect(Math.max(...xs)).toBeCloseTo(Math.tan(Math.PI / 6), 3);
  expect(inspected.bimodal).toBe(true);
  expect(Math.abs(inspected.lobes.renormalized.centre[0])).toBeLessThan(1e-3); // flat: between the spikes
  await expect(page.locator('.nm-inspector-verdict')).toContainText('Two spikes, one blob');
  // Clicking a level-1 thumbnail picks a texel there; bumps give one cloud, not two spikes.
  await page.evaluate((id) => { window.fresnelLab.hosts[id].set({ map: 'bumps' }); return window.fresnelLab.panels[id].whenBuilt(); }, PANEL);
  const cell = page.locator('.nm-strip-cell').nth(1);
  const box = await cell.boundingBox();
  await cell.click({ position: { x: 5, y: box.height - 4 } }); // near the bottom-left corner: texel (0, 0)
  await expect.poll(() => page.evaluate((id) => window.fresnelLab.hosts[id].values.texelLevel, PANEL)).toBe(1);
  await expect(page.locator('.nm-inspector-verdict')).not.toContainText('Two spikes');
  await expect(page.locator('.nm-costs tr.nm-current th')).toHaveText('Toksvig');
});

test('shimmer meter: renormalized flickers more than Toksvig under sub-pixel camera moves', async ({ page }) => {
  await openLab(page, `${URL}&truth=false&map=bumps`);
  await expect(page.locator('.nm-shimmer')).toContainText('press');
  await page.getByRole('button', { name: /Measure shimmer/ }).click();
  await expect(page.locator('.nm-shimmer')).toContainText('Shimmer (mean brightness change');
  const shimmer = await page.evaluate((id) => window.fresnelLab.panels[id].shimmer, PANEL);
  for (const good of ['toksvig', 'clean', 'lean', 'vmf']) expect(shimmer[good]).toBeLessThan(shimmer.renormalized);
  await expect(page.locator('.panel-description')).toContainText(`Shimmer of Toksvig: ${shimmer.toksvig.toFixed(4)}`);
  // A change of view makes the old numbers stale.
  await page.evaluate((id) => window.fresnelLab.hosts[id].set({ viewEl: 12 }), PANEL);
  await expect(page.locator('.nm-shimmer')).toContainText('press');
});

// Mean λ over plane pixels and the column of the brightest plane pixel, from the technique pass.
function readPlane(page, values) {
  return page.evaluate(async ([id, v]) => {
    window.fresnelLab.hosts[id].set(v);
    const panel = window.fresnelLab.panels[id];
    await panel.whenBuilt();
    const image = panel.scene.readTechnique();
    const [width] = panel.scene.uniforms.uResolution.value;
    let lod = 0;
    let count = 0;
    let best = -1;
    let column = -1;
    for (let o = 0, p = 0; o < image.length; o += 4, p++) {
      if (image[o + 3] < 0) continue;
      lod += image[o + 3];
      count++;
      const y = image[o] + image[o + 1] + image[o + 2];
      if (y > best) { best = y; column = p % width; }
    }
    return { lod: lod / count, column: column / width, max: panel.scene.maxAnisotropy };
  }, [PANEL, values]);
}

test('anisotropic filtering samples finer levels; the point light places the highlight', async ({ page }) => {
  await openLab(page, `${URL}&truth=false&view=technique`);
  const trilinear = await readPlane(page, { anisotropy: '1' });
  const aniso = await readPlane(page, { anisotropy: '16' });
  await expect(page.locator('.nm-summary')).toContainText('anisotropic filtering');
  // At 8° below the horizon the footprint is long and thin: N taps along it lower λ by up to log2 N.
  if (aniso.max > 1) expect(aniso.lod).toBeLessThan(trilinear.lod - 0.5);
  else expect(aniso.lod).toBeCloseTo(trilinear.lod, 6);
  // Light ahead: the glint is in the middle; light to the left (negative azimuth): left of it.
  const ahead = await readPlane(page, { anisotropy: '1', lightAz: 0 });
  const left = await readPlane(page, { lightAz: -40 });
  expect(Math.abs(ahead.column - 0.5)).toBeLessThan(0.05);
  expect(left.column).toBeLessThan(ahead.column - 0.1);
});

test('noise and mixed maps: the ground truth runs their GLSL twins, and keeping the variance still pays', async ({ page }) => {
  test.setTimeout(60_000);
  await openLab(page, `${URL}&map=mixed&truthSamples=32`);
  await page.waitForFunction((id) => window.fresnelLab.panels[id]?.scene.state.errors, PANEL, { timeout: 45_000 });
  const { errors, kind } = await page.evaluate((id) => {
    const { scene } = window.fresnelLab.panels[id];
    return { errors: scene.state.errors, kind: scene.uniforms.uMapKind.value };
  }, PANEL);
  expect(kind).toBe(4);
  for (const good of ['toksvig', 'clean', 'lean']) expect(errors[good].rmse, good).toBeLessThan(errors.naive.rmse);
  // A 2-channel noise map is rebuilt in the worker and drawn with the noise kind.
  const noise = await page.evaluate(async (id) => {
    window.fresnelLab.hosts[id].set({ map: 'noise', channels: '2' });
    const panel = window.fresnelLab.panels[id];
    await panel.whenBuilt();
    return { kind: panel.scene.uniforms.uMapKind.value, channels: panel.chains.naive.channels };
  }, PANEL);
  expect(noise).toEqual({ kind: 3, channels: 2 });
});

test('a lost context comes back: textures and targets are rebuilt and the picture is the same', async ({ page }) => {
  await openLab(page, `${URL}&truth=false`);
  await page.evaluate((id) => window.fresnelLab.panels[id].whenBuilt(), PANEL);
  const before = await page.evaluate((id) => Array.from(window.fresnelLab.panels[id].scene.readTechnique()), PANEL);
  await page.evaluate((id) => new Promise((resolve) => {
    const { scene } = window.fresnelLab.panels[id];
    window.loseContext = scene.gl.getExtension('WEBGL_lose_context');
    scene.gl.canvas.addEventListener('webglcontextlost', () => resolve(), { once: true });
    window.loseContext.loseContext();
  }), PANEL);
  const frames = await page.evaluate((id) => window.fresnelLab.hosts[id].frames, PANEL);
  await page.evaluate(() => window.loseContext.restoreContext());
  await expect.poll(() => page.evaluate((id) => window.fresnelLab.hosts[id].frames, PANEL)).toBeGreaterThan(frames);
  const after = await page.evaluate((id) => Array.from(window.fresnelLab.panels[id].scene.readTechnique()), PANEL);
  expect(after.length).toBe(before.length);
  expect(after.some((v) => v !== 0)).toBe(true);
  expect(after.every((v, i) => v === before[i])).toBe(true);
});

test('in the pseudo-locale every word is the catalogue\'s: captions, table, plot, strip, inspector, shimmer', async ({ page }) => {
  test.setTimeout(60_000);
  await openInPseudoLocale(page, `${URL}&map=grooves&truthSamples=32`);
  await page.evaluate((id) => window.fresnelLab.panels[id].whenBuilt(), PANEL);
  expect(await panelWordsOutside(page), 'while the truth converges').toEqual([]);
  await page.waitForFunction((id) => window.fresnelLab.panels[id]?.scene.state.errors, PANEL, { timeout: 45_000 });
  await page.evaluate((id) => window.fresnelLab.panels[id].runs.measureShimmer(), PANEL);
  await expect(page.locator('.nm-errors tbody tr')).toHaveCount(6);
  expect(await panelWordsOutside(page), 'with the errors and the shimmer').toEqual([]);
  await page.evaluate((id) => window.fresnelLab.hosts[id].set({ view: 'difference', level: 3, anisotropy: '4', truth: false }), PANEL);
  await expect(page.locator('.nm-pending')).toBeVisible();
  expect(await panelWordsOutside(page), 'the truth off, a forced level').toEqual([]);
});
