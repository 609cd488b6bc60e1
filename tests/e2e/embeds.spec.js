// Every panel's embed, opened once on a desktop and once on a phone turned tablet, with every check
// that reads the same page: on the desktop the accessibility audit, the panel contract
// (panelContract.js), seeded keys (of which one at least must reach a control) and a seeded fuzz of
// the message door, markup from outside that must stay text, and a valid `set` followed afterwards;
// on the phone (390×844, then 768×1024 in the same page) the layout at both sizes and the audit on
// the phone. FUZZ_SEED=<n> replays the fuzz.
import { test, expect, openLab, settledFrames } from './fixtures.js';
import { PANELS } from '../../src/panels/manifest.js';
import { seriousViolations } from './audit.js';
import { expectPanelContract, probeValue } from './panelContract.js';
import { SEED, expectKeysReached, expectSound, focusPanel, fuzzKeys } from './keyFuzz.js';
import { XSS, injected, randomMessages, sendMessages } from './doorFuzz.js';
import { layoutProblems } from './layout.js';

const schemas = Object.fromEntries(await Promise.all(PANELS.map(async ({ id }) => [id, (await import(`../../src/panels/${id}/schema.js`)).schema])));

/** A valid set the panel must still follow: every key to another valid value. */
async function expectFollows(page, id) {
  const schema = schemas[id];
  const update = Object.fromEntries(Object.entries(schema).filter(([, spec]) => spec.type !== 'text').map(([key, spec]) => [key, probeValue(spec)]));
  const result = await page.evaluate(([i, u]) => window.fresnelLab.hosts[i].set(u), [id, update]);
  expect(result.rejected, `${id} refused a valid set`).toEqual([]);
  expect(await page.evaluate(([i, keys]) => keys.map((k) => window.fresnelLab.hosts[i].values[k]), [id, Object.keys(update)]))
    .toEqual(Object.values(update));
}

for (const [n, entry] of PANELS.entries()) {
  const { id } = entry;
  // An animated panel is checked with its animation off: then it, too, draws only on change; the
  // normal-map viewer without its progressive ground truth, which nothing here is about.
  const still = `${entry.animates ? `&${entry.animates}=false` : ''}${id === 'normal-mips' ? '&truth=false' : ''}`;

  test(`${id}: audit, contract, seeded keys and messages, outside text kept as text (seed ${SEED + n + 1})`, async ({ page }) => {
    test.setTimeout(150_000);
    await openLab(page, `./embed.html?panel=${id}${still}`);
    expect(await seriousViolations(page), 'accessibility audit').toEqual([]);
    await expectPanelContract(page, entry);

    await focusPanel(page);
    const pressed = await fuzzKeys(page, SEED + n + 1, 50);
    await expectSound(page, `${id} after ${pressed.join(' ')}`);
    await expectKeysReached(page, `${id} after ${pressed.join(' ')}`);

    // The message door: what a deck's script might send, valid or not; errors answered, nothing thrown.
    await page.evaluate(() => {
      window.__answers = [];
      window.addEventListener('message', (event) => { if (event.data?.type === 'fresnel-lab:error') window.__answers.push(event.data.message); });
    });
    const messages = randomMessages(SEED + 1000 + n, Object.keys(schemas[id]), 40);
    await sendMessages(page, messages);
    // Markup as values (in every text the panel takes, such as the shader lab's code, whose
    // compile log quotes it), as keys and as control names: refused or shown, always as text.
    const texts = Object.keys(schemas[id]).filter((key) => schemas[id][key].type === 'text');
    await sendMessages(page, XSS.flatMap((markup) => [
      JSON.stringify({ type: 'fresnel-lab:set', params: { [markup]: markup, [Object.keys(schemas[id])[0]]: markup } }),
      ...texts.map((key) => JSON.stringify({ type: 'fresnel-lab:set', params: { [key]: `float fresnel() { ${markup} }` } })),
      JSON.stringify({ type: 'fresnel-lab:lock', keys: [markup] }),
    ]));
    await expectSound(page, `${id} after messages ${messages.join(' ').slice(0, 400)}`);
    expect(await injected(page), 'markup from outside became elements').toEqual([]);
    const answers = await page.evaluate(() => window.__answers);
    expect(answers.length, 'bad messages are answered with an error').toBeGreaterThan(0);
    expect(answers.every((text) => typeof text === 'string' && text.length > 0 && text.length < 2000)).toBe(true);
    await page.evaluate(() => window.postMessage({ type: 'fresnel-lab:unlock' }, '*'));
    await expectFollows(page, id);
  });

}


// One phone for every embed, as one tab: a tab's start and a cold compile are most of what a load costs.
test.describe('on a phone', () => {
  let phone = null;
  const problems = [];
  test.beforeAll(async ({ browser }, workerInfo) => {
    const context = await browser.newContext({ baseURL: workerInfo.project.use.baseURL, viewport: { width: 390, height: 844 }, isMobile: true, hasTouch: true });
    phone = await context.newPage();
    phone.on('pageerror', (error) => problems.push(error.message));
    phone.on('console', (message) => { if (message.type() === 'error') problems.push(message.text()); });
  });
  test.afterAll(async () => { await phone?.context().close(); });

  for (const entry of PANELS) {
    const { id } = entry;
    const still = `${entry.animates ? `&${entry.animates}=false` : ''}${id === 'normal-mips' ? '&truth=false' : ''}`;
    test(`${id}: on a phone and a tablet it fits and cuts no label; on the phone it passes the audit`, async () => {
      test.setTimeout(120_000);
      const page = phone;
      problems.length = 0;
      await page.setViewportSize({ width: 390, height: 844 });
      await openLab(page, `embed.html?panel=${id}${still}`);
      for (const size of [{ width: 390, height: 844 }, { width: 768, height: 1024 }]) {
        await page.setViewportSize(size);
        await expect.poll(() => page.evaluate(() => document.documentElement.clientWidth)).toBe(size.width);
        await settledFrames(page, id);
        expect(await layoutProblems(page), `${size.width} px`).toEqual([]);
        // The audit at the phone's width, where the layout changes most; the tablet's lies between
        // it and the desktop's, audited above.
        if (size.width === 390) expect(await seriousViolations(page), `audit at ${size.width} px`).toEqual([]);
      }
      expect(problems, 'the page logged errors').toEqual([]);
    });
  }
});
