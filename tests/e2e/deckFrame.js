// A panel embedded in a plain page of the test server (a deck), with every message it posts kept:
// the message API seen from the deck's side.
import { expect, openDeck } from './fixtures.js';

/**
 * Opens the deck page with embed.html?<query> in an iframe (#panel) and waits for `ready`.
 * Returns helpers: send(message), all(type) (the data of every message of that type so far),
 * count(type), waitFor(type, count) (resolves the newest one), delivered(message) and frame (the
 * embed's Frame).
 */
export async function embedInDeck(page, baseURL, query, { width = 900, height = 700, waitReady = true } = {}) {
  await openDeck(page);
  await page.evaluate(([src, w, h]) => {
    window.__log = [];
    window.addEventListener('message', (event) => window.__log.push({ origin: event.origin, data: event.data }));
    const frame = document.createElement('iframe');
    frame.id = 'panel';
    frame.src = src;
    frame.width = w;
    frame.height = h;
    document.body.append(frame);
  }, [`${baseURL}embed.html?${query}`, width, height]);
  const all = (type) => page.evaluate((t) => window.__log.filter((e) => e.data?.type === t).map((e) => e.data), type);
  const count = async (type) => (await all(type)).length;
  const api = {
    send: (message) => page.evaluate((m) => document.getElementById('panel').contentWindow.postMessage(m, '*'), message),
    all,
    count,
    async waitFor(type, n = 1) {
      await expect.poll(() => count(type), { message: `${n} × ${type}` }).toBeGreaterThanOrEqual(n);
      return (await all(type)).at(-1);
    },
    get frame() { return page.frames().find((f) => f.url().includes('embed.html')); },
    /**
     * Sends a message and waits until the embed's window has dispatched it: a listener added now,
     * after the lab's own, hears it once the lab's has run. The acknowledgement that a message the
     * lab must ignore has reached it, for panels that answer nothing.
     */
    async delivered(message) {
      const heard = () => api.frame.evaluate(() => window.__heard?.length ?? 0);
      await api.frame.evaluate(() => {
        if (window.__heard) return;
        window.__heard = [];
        window.addEventListener('message', (event) => window.__heard.push(event.data));
      });
      const before = await heard();
      await api.send(message);
      await expect.poll(heard, { message: 'the embed received the message' }).toBe(before + 1);
    },
  };
  await expect.poll(() => Boolean(api.frame), { message: 'the embed frame' }).toBe(true);
  if (waitReady) await api.waitFor('fresnel-lab:ready');
  return api;
}
