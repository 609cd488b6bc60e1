// One browser tab that the tests of a worker take in turn (fixtures.js). A new tab per test pays for
// a renderer process and a cold compile of the lab's scripts every time; this one keeps both. What
// a test could leave behind is undone before the next: other tabs closed, the page on about:blank,
// storage, cookies, permissions and emulated media reset, the listeners, init scripts and routes the
// test added removed. What this does not undo (extra headers, a HAR, an exposed function) is refused
// while the tab is shared.

/** Methods whose effect outlives a test, on the page and on its context: undone after it (their Disposable). */
const UNDONE = ['addInitScript', 'route'];
/** The same, with nothing here to undo them: refused. */
const REFUSED = ['routeFromHAR', 'routeWebSocket', 'exposeFunction', 'exposeBinding', 'setExtraHTTPHeaders'];

/** Names of the events that have listeners, with those listeners, as they are now. */
const listenersOf = (emitter) => new Map(emitter.eventNames().map((name) => [name, [...emitter.listeners(name)]]));

/**
 * The shared tab, blank: made on first use, else cleaned of the test before. `shared` is the worker's
 * { context, page, cdp, listeners }.
 */
export async function blankPage(shared, baseURL, viewport) {
  const { context } = shared;
  if (shared.page?.isClosed()) shared.page = null;
  if (!shared.page) {
    shared.page = await context.newPage();
    shared.cdp = await context.newCDPSession(shared.page);
  }
  const { page, cdp } = shared;
  for (const other of context.pages()) if (other !== page) await other.close();
  await page.goto('about:blank');
  // Local and session storage (Chromium clears both as "local_storage"), of the lab's origin and of pages opened from disk.
  for (const origin of [new URL(baseURL).origin, 'file://']) {
    await cdp.send('Storage.clearDataForOrigin', { origin, storageTypes: 'local_storage,indexeddb,cache_storage,service_workers' });
  }
  await context.clearCookies();
  await context.clearPermissions();
  await context.setOffline(false);
  await page.emulateMedia({ media: null, colorScheme: 'light', reducedMotion: 'no-preference', forcedColors: 'none', contrast: 'no-preference' });
  if (viewport) await page.setViewportSize(viewport);
  shared.listeners = { page: listenersOf(page), context: listenersOf(context) };
  return page;
}

/**
 * Watches the shared page and its context for the test: what the undone methods add is kept to be
 * disposed of, the refused ones throw. Returns what undoes it all and puts the methods back.
 */
export function guardShared(page) {
  const targets = [page, page.context()];
  const added = [];
  for (const target of targets) {
    for (const name of UNDONE) {
      const method = target[name];
      target[name] = async (...args) => {
        const disposable = await method.apply(target, args);
        added.push(disposable);
        return disposable;
      };
    }
    for (const name of REFUSED) {
      target[name] = () => {
        throw new Error(`${name} outlives the test in a shared page: give the test its own with test.use({ ownPage: true })`);
      };
    }
  }
  return async () => {
    for (const target of targets) for (const name of [...UNDONE, ...REFUSED]) delete target[name];
    for (const disposable of added.reverse()) await disposable?.dispose?.().catch(() => {});
    for (const target of targets) await target.unrouteAll({ behavior: 'ignoreErrors' });
  };
}

/** After a test: its listeners removed; a tab whose test failed is closed, so the next starts anew. */
export async function releasePage(shared, passed) {
  const { page, context, listeners } = shared;
  if (!page) return;
  for (const [emitter, before] of [[page, listeners.page], [context, listeners.context]]) {
    for (const name of emitter.eventNames()) {
      const kept = before.get(name) ?? [];
      for (const listener of emitter.listeners(name)) if (!kept.includes(listener)) emitter.off(name, listener);
    }
  }
  if (!passed && !page.isClosed()) {
    await page.close();
    shared.page = null;
  }
}
