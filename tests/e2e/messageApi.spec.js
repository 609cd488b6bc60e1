// Message API version 1, from the deck's side: changes with their source, reset, snapshot,
// locked and hidden controls, theme and motion, pause and resume, forwarded keys, the deck's
// origin, and what a good guest does with the wheel and a refused clipboard.
import { test, expect, openLab } from './fixtures.js';
import { embedInDeck } from './deckFrame.js';

const inFrame = (api, fn, arg) => api.frame.evaluate(fn, arg);
const hero = (api) => inFrame(api, () => ({ ...window.fresnelLab.hosts.spheres.values }));

test('ready carries the API version; every change is announced with its source and keys, a drag once', async ({ page, baseURL }) => {
  const api = await embedInDeck(page, baseURL, 'panel=spheres&nT=1.7');
  expect(await api.waitFor('fresnel-lab:ready')).toMatchObject({ apiVersion: 1, panel: 'spheres', params: { nT: 1.7 } });
  expect(await api.waitFor('fresnel-lab:changed')).toMatchObject({ source: 'url', keys: ['nT'] });
  await api.send({ type: 'fresnel-lab:set', params: { nI: 1.2 } });
  expect(await api.waitFor('fresnel-lab:changed', 2)).toMatchObject({ source: 'api', keys: ['nI'], params: { nI: 1.2, nT: 1.7 } });
  // Ten changes made in the panel within one drag arrive as one message, with `state` as before.
  await inFrame(api, () => {
    for (let i = 1; i <= 10; i += 1) window.fresnelLab.hosts.spheres.set({ viewAz: 10 + i }, { source: 'user' });
  });
  expect(await api.waitFor('fresnel-lab:changed', 3)).toMatchObject({ source: 'user', keys: ['viewAz'], params: { viewAz: 20 } });
  // A later change of the deck's is announced after anything still gathered from the drag.
  await api.send({ type: 'fresnel-lab:set', params: { nI: 1.3 } });
  expect(await api.waitFor('fresnel-lab:changed', 4)).toMatchObject({ source: 'api', keys: ['nI'] });
  expect((await api.all('fresnel-lab:changed')).filter((m) => m.source === 'user')).toHaveLength(1);
  expect((await api.all('fresnel-lab:state')).at(-1).params.viewAz).toBe(20);
});

test('code kept in this browser is where an embedded shader lab starts: ready carries it, and no change is announced', async ({ page, baseURL }) => {
  const code = 'float fresnel(float c, float a, float b) { return 1.0; }';
  await page.goto('./');
  await page.evaluate((text) => localStorage.setItem('fresnel-lab:shader-lab:schlick', text), code);
  const api = await embedInDeck(page, baseURL, 'panel=shader-lab');
  expect((await api.waitFor('fresnel-lab:ready')).params.code).toBe(code);
  await api.send({ type: 'fresnel-lab:get' });
  await api.waitFor('fresnel-lab:state');
  // The answer to get came after anything the load sent: no change among them.
  expect(await api.all('fresnel-lab:changed')).toEqual([]);
  await page.evaluate(() => localStorage.removeItem('fresnel-lab:shader-lab:schlick'));
});

test('reset returns to the link\'s values or to the defaults', async ({ page, baseURL }) => {
  const api = await embedInDeck(page, baseURL, 'panel=spheres&nT=1.7');
  await api.send({ type: 'fresnel-lab:set', params: { nT: 2.2, nI: 1.1 } });
  await expect.poll(async () => (await hero(api)).nT).toBe(2.2);
  await api.send({ type: 'fresnel-lab:reset' });
  await expect.poll(async () => (await hero(api))).toMatchObject({ nI: 1, nT: 1.7 });
  await api.send({ type: 'fresnel-lab:reset', to: 'defaults' });
  await expect.poll(async () => (await hero(api)).nT).toBe(1.5);
  expect((await api.all('fresnel-lab:state')).at(-1).params.nT).toBe(1.5);
});

test('snapshot answers a PNG at the requested size, the CSV and the state', async ({ page, baseURL }) => {
  const api = await embedInDeck(page, baseURL, 'panel=spheres&nT=1.33');
  await api.waitFor('fresnel-lab:rendered');
  await api.send({ type: 'fresnel-lab:snapshot', width: 300, id: 'slide-4' });
  const shot = await api.waitFor('fresnel-lab:snapshot');
  expect(shot).toMatchObject({ panel: 'spheres', id: 'slide-4', width: 300, params: { nT: 1.33 } });
  const size = await page.evaluate(async (url) => {
    const image = new Image();
    image.src = url;
    await image.decode();
    return [image.naturalWidth, image.naturalHeight];
  }, shot.png);
  expect(size).toEqual([300, shot.height]);
  expect(shot.height).toBeGreaterThan(50);
  expect(shot.csv.split('\n')[0]).toContain(',');
  expect(shot.csv.split('\n').length).toBeGreaterThan(10);
  // A plot-only panel has no picture to give, but its numbers.
  const plot = await embedInDeck(page, baseURL, 'panel=schlick');
  await plot.send({ type: 'fresnel-lab:snapshot' });
  const numbers = await plot.waitFor('fresnel-lab:snapshot');
  expect(numbers.csv.length).toBeGreaterThan(100);
});

test('controls lock, unlock, hide and show, from the link and by message', async ({ page, baseURL }) => {
  const api = await embedInDeck(page, baseURL, 'panel=spheres&lock=nT&hide=nI');
  const control = (label) => api.frame.locator('.lil-gui .lil-controller', { hasText: label });
  await expect(control('n_t (sphere)')).toHaveClass(/lil-disabled/);
  await expect(control('n_i (incident side)')).toBeHidden();
  // A locked value changes only when the deck changes it.
  await inFrame(api, () => window.fresnelLab.hosts.spheres.set({ nT: 2 }, { source: 'user' }));
  expect((await hero(api)).nT).toBe(1.5);
  // So do the panel's own controls that change it, and a swap that would change it is refused whole.
  await expect(control('Sphere material')).toHaveClass(/lil-disabled/);
  await expect(control('Swap n_i')).toHaveClass(/lil-disabled/);
  await inFrame(api, () => window.fresnelLab.hosts.spheres.set({ nI: 1.5, nT: 1 }, { source: 'user' }));
  expect(await hero(api)).toMatchObject({ nI: 1, nT: 1.5 });
  await api.send({ type: 'fresnel-lab:set', params: { nT: 2 } });
  await expect.poll(async () => (await hero(api)).nT).toBe(2);
  await api.send({ type: 'fresnel-lab:unlock', keys: ['nT'] });
  await expect(control('n_t (sphere)')).not.toHaveClass(/lil-disabled/);
  await api.send({ type: 'fresnel-lab:hide' });
  await expect(api.frame.locator('.panel-side')).toBeHidden();
  await api.send({ type: 'fresnel-lab:show' });
  await expect(api.frame.locator('.panel-side')).toBeVisible();
  await expect(control('n_i (incident side)')).toBeVisible();
  await api.send({ type: 'fresnel-lab:lock', keys: ['nothing'] });
  expect((await api.waitFor('fresnel-lab:error')).message).toContain('nothing');
  // What a locked value would have followed gives way: the camera orbits with its distance locked,
  // and changing-specular draws the light it is given with the view's elevation locked.
  const orbit = await embedInDeck(page, baseURL, 'panel=spheres&lock=viewDist');
  await orbit.frame.locator('canvas').first().focus();
  await page.keyboard.press('ArrowLeft');
  await expect.poll(async () => (await hero(orbit)).viewAz).not.toBe(0);
  const linked = await embedInDeck(page, baseURL, 'panel=changing-specular&lock=viewEl');
  await linked.waitFor('fresnel-lab:rendered');
  const drawn = await linked.count('fresnel-lab:rendered');
  await linked.send({ type: 'fresnel-lab:set', params: { lightEl: 50 } });
  await linked.waitFor('fresnel-lab:rendered', drawn + 1);
  expect(await inFrame(linked, () => ({ ...window.fresnelLab.hosts['changing-specular'].values }))).toMatchObject({ lightEl: 50, viewEl: 30 });
  const bare = await embedInDeck(page, baseURL, 'panel=schlick&controls=0');
  await expect(bare.frame.locator('.panel-side')).toBeHidden();
  await expect(bare.frame.locator('.sk-plot canvas, canvas').first()).toBeVisible();
});

test('theme, projector mode and reduced motion come from the link and from messages, and are not stored', async ({ page, baseURL }) => {
  const api = await embedInDeck(page, baseURL, 'panel=refraction-waves&theme=light&projector=1&reducedMotion=1');
  const look = () => inFrame(api, () => ({
    theme: document.documentElement.dataset.theme,
    projector: document.documentElement.classList.contains('projector'),
    stored: (() => { try { return localStorage.getItem('fresnel-lab:theme'); } catch { return 'blocked'; } })(),
    play: window.fresnelLab.hosts['refraction-waves'].values.play,
  }));
  expect(await look()).toEqual({ theme: 'light', projector: true, stored: null, play: false });
  await api.send({ type: 'fresnel-lab:theme', theme: 'dark' });
  await api.send({ type: 'fresnel-lab:projector', on: false });
  await api.send({ type: 'fresnel-lab:set', params: { play: true } });
  await expect.poll(look).toEqual({ theme: 'dark', projector: false, stored: null, play: true });
  await api.send({ type: 'fresnel-lab:reducedMotion', on: true });
  await expect.poll(async () => (await look()).play).toBe(false);
  const bad = await embedInDeck(page, baseURL, 'panel=schlick&theme=purple&controls=maybe');
  await expect(bad.frame.locator('.notice')).toContainText('theme=purple');
  await expect(bad.frame.locator('.notice')).toContainText('controls=maybe');
});

test('size tells the deck the content height, again when it changes', async ({ page, baseURL }) => {
  const api = await embedInDeck(page, baseURL, 'panel=schlick', { height: 300 });
  await api.waitFor('fresnel-lab:rendered');
  // The newest size against the page's height now (the page may still be settling: formulas, plot).
  const newest = async () => ({ told: (await api.all('fresnel-lab:size')).at(-1)?.height, now: await inFrame(api, () => document.body.scrollHeight) });
  await expect.poll(async () => { const { told, now } = await newest(); return told === now; }).toBe(true);
  const first = (await api.all('fresnel-lab:size')).at(-1);
  expect(first).toMatchObject({ type: 'fresnel-lab:size', panel: 'schlick' });
  expect(first.height).toBeGreaterThan(300); // taller than its frame: the deck can fit the frame to it
  await api.send({ type: 'fresnel-lab:projector', on: true }); // larger type: a taller page
  await expect.poll(async () => { const { told, now } = await newest(); return told === now && told > first.height; }).toBe(true);
});

test('pause (and reveal.js\'s slide:stop) frees the WebGL context; resume restores the same picture', async ({ page, baseURL }) => {
  const api = await embedInDeck(page, baseURL, 'panel=spheres&viewAz=40&nT=1.8');
  await api.waitFor('fresnel-lab:rendered');
  const picture = () => inFrame(api, () => window.fresnelLab.panels.spheres?.png?.() ?? null);
  const live = () => inFrame(api, () => window.fresnelLab.contexts.live);
  const before = await picture();
  expect(await live()).toBe(1);
  for (const [stop, start] of [['slide:stop', 'slide:start'], [{ type: 'fresnel-lab:pause' }, { type: 'fresnel-lab:resume' }]]) {
    await api.send(stop);
    await expect.poll(live).toBe(0);
    expect(await inFrame(api, () => window.fresnelLab.hosts.spheres.mounted)).toBe(false);
    const frames = await api.count('fresnel-lab:rendered');
    await api.send(start);
    await api.waitFor('fresnel-lab:rendered', frames + 1);
    expect(await live()).toBe(1);
    expect(await picture()).toBe(before);
  }
});

test('keys no control used go to the deck; keys a control or the canvas uses do not', async ({ page, baseURL }) => {
  const api = await embedInDeck(page, baseURL, 'panel=spheres');
  await api.frame.locator('.embed-title').click();
  await page.keyboard.press('PageDown');
  await page.keyboard.press('ArrowRight');
  await expect.poll(async () => (await api.all('fresnel-lab:key')).map((m) => m.key)).toEqual(['PageDown', 'ArrowRight']);
  await api.frame.locator('.sph-canvas, canvas').first().focus();
  await page.keyboard.press('ArrowLeft'); // orbits the view
  await api.frame.locator('.lil-gui input').first().focus();
  await page.keyboard.press('ArrowUp');
  await api.frame.getByRole('button', { name: 'Export CSV' }).focus();
  await page.keyboard.press(' '); // presses the button, so it must not turn the slide as well
  // A key that does go to the deck, pressed last, arrives after any the others sent.
  await api.frame.locator('.embed-title').click();
  await page.keyboard.press('End');
  await expect.poll(async () => (await api.all('fresnel-lab:key')).map((m) => m.key)).toEqual(['PageDown', 'ArrowRight', 'End']);
});

test('parentOrigin: messages go only to that origin and only its messages are heard', async ({ page, baseURL }) => {
  const own = new URL(baseURL).origin;
  const api = await embedInDeck(page, baseURL, `panel=spheres&parentOrigin=${encodeURIComponent(own)}`);
  expect((await api.all('fresnel-lab:ready'))[0].apiVersion).toBe(1);
  await api.send({ type: 'fresnel-lab:set', params: { nT: 2.1 } });
  await expect.poll(async () => (await hero(api)).nT).toBe(2.1);
  const other = await embedInDeck(page, baseURL, 'panel=spheres&parentOrigin=https://deck.example', { waitReady: false });
  await expect.poll(() => inFrame(other, () => window.fresnelLab?.hosts.spheres?.frames ?? 0)).toBeGreaterThan(0);
  await other.delivered({ type: 'fresnel-lab:set', params: { nT: 2.1 } });
  expect((await hero(other)).nT).toBe(1.5);
  expect(await other.count('fresnel-lab:ready')).toBe(0);
  // An origin that cannot be used leaves the panel to no page rather than to every page.
  const closed = await embedInDeck(page, baseURL, 'panel=spheres&parentOrigin=deck.example', { waitReady: false });
  await expect(closed.frame.locator('.notice')).toContainText('no page may drive this panel');
  // The notice comes before the panel's module: the message goes to a panel that is there.
  await expect.poll(() => inFrame(closed, () => window.fresnelLab?.hosts.spheres?.frames ?? 0)).toBeGreaterThan(0);
  await closed.delivered({ type: 'fresnel-lab:set', params: { nT: 2.1 } });
  expect((await hero(closed)).nT).toBe(1.5);
  expect(await closed.count('fresnel-lab:ready')).toBe(0);
});

test('malformed messages are ignored without an answer', async ({ page, baseURL }) => {
  const api = await embedInDeck(page, baseURL, 'panel=spheres');
  for (const message of [
    { type: 'fresnel-lab:reset', to: 'yesterday' }, { type: 'fresnel-lab:snapshot', width: -4 }, { type: 'fresnel-lab:snapshot', width: 1e6 },
    { type: 'fresnel-lab:lock', keys: 'nT' }, { type: 'fresnel-lab:lock', keys: [1, 2] }, { type: 'fresnel-lab:theme', theme: 'pink' },
    { type: 'fresnel-lab:projector', on: 'yes' }, { type: 'fresnel-lab:set', params: [1] }, { type: 'fresnel-lab:nonsense' },
    'slide:later', 42, null, [],
  ]) await api.send(message);
  // Answers go out in the order the messages came: the answers to a get and a snapshot sent last
  // come after any the malformed ones drew (a snapshot is drawn after those asked before it).
  await api.send({ type: 'fresnel-lab:get' });
  await api.send({ type: 'fresnel-lab:snapshot', id: 'last' });
  expect(await api.waitFor('fresnel-lab:snapshot')).toMatchObject({ id: 'last' });
  expect(await api.count('fresnel-lab:state')).toBe(1);
  expect(await api.count('fresnel-lab:snapshot')).toBe(1);
  for (const type of ['fresnel-lab:error', 'fresnel-lab:changed']) expect(await api.count(type), type).toBe(0);
  expect(await hero(api)).toMatchObject({ nI: 1, nT: 1.5 });
});

test('the wheel over the hero scrolls the page until the view is picked; then it zooms', async ({ page }) => {
  await openLab(page, './');
  const canvas = page.locator('section[data-panel="spheres"] canvas').first();
  const box = await canvas.boundingBox();
  await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
  const distance = () => page.evaluate(() => window.fresnelLab.hosts.spheres.values.viewDist);
  const start = await distance();
  await page.mouse.wheel(0, 300);
  await expect.poll(() => page.evaluate(() => window.scrollY)).toBeGreaterThan(0);
  expect(await distance()).toBe(start);
  await page.evaluate(() => window.scrollTo(0, 0));
  await canvas.click();
  await page.mouse.wheel(0, 300);
  await expect.poll(distance).toBeGreaterThan(start);
});

test('where the clipboard is refused, the link is offered selected; the embed code allows fullscreen and the clipboard', async ({ page }) => {
  await page.addInitScript(() => {
    Object.defineProperty(navigator, 'clipboard', { value: { writeText: () => Promise.reject(new Error('refused')) } });
  });
  await openLab(page, './embed.html?panel=schlick');
  await page.getByRole('button', { name: 'Copy embed code' }).click();
  const field = page.locator('.copy-fallback');
  await expect(field).toBeFocused();
  const offered = await field.inputValue();
  expect(offered).toContain('allow="fullscreen; clipboard-write"');
  expect(await field.evaluate((f) => f.selectionEnd - f.selectionStart)).toBe(offered.length);
  await page.keyboard.press('Escape');
  await expect(field).toHaveCount(0);
});
