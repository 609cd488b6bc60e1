// The Content-Security-Policy a built page carries as a meta (scripts/contentSecurityPolicy.js):
// it is there before any script, nothing the page does is refused by it, and it refuses what an
// injected piece of markup would try.
import { expect } from './fixtures.js';

/** Records the page's CSP violations from its first script on (window.cspViolations). */
export const recordViolations = (page) => page.addInitScript(() => {
  window.cspViolations = [];
  document.addEventListener('securitypolicyviolation', (e) => {
    window.cspViolations.push(`${e.effectiveDirective} ${e.blockedURI} (${e.sourceFile}:${e.lineNumber})`);
  });
});

export const violations = (page) => page.evaluate(() => window.cspViolations);

/** The page's policy meta: present, first in <head> before any script; returns its policy. */
export async function policyMeta(page) {
  const meta = await page.evaluate(() => {
    const found = document.querySelectorAll('meta[http-equiv="Content-Security-Policy" i]');
    const children = [...document.head.children];
    const firstScript = children.findIndex((e) => e.localName === 'script' || (e.localName === 'link' && /preload/.test(e.rel)));
    return found.length === 1 ? { policy: found[0].content, at: children.indexOf(found[0]), firstScript } : { count: found.length };
  });
  expect(meta.policy, 'one policy meta').toBeTruthy();
  expect(meta.at, 'the meta comes before any script').toBeLessThan(meta.firstScript < 0 ? Infinity : meta.firstScript);
  expect(meta.policy).not.toMatch(/unsafe-inline|unsafe-eval|\*/);
  return meta.policy;
}

/**
 * What an injection of markup would try is refused: an inline script, an inline event handler and
 * a script from another host. None runs, and each is a violation. (Whether eval is refused cannot be
 * seen from here: the test's own evaluate is exempt; the policy has no 'unsafe-eval', checked above.)
 */
export async function expectInjectionRefused(page) {
  const before = (await violations(page)).length;
  await page.evaluate(() => {
    const script = document.createElement('script');
    script.textContent = 'window.injected = "inline";';
    const image = document.createElement('img');
    image.setAttribute('onerror', 'window.injected = "handler";');
    image.src = 'data:,not an image';
    const remote = document.createElement('script');
    remote.src = 'https://lab.invalid/injected.js';
    document.body.append(script, image, remote);
  });
  await expect.poll(async () => (await violations(page)).slice(before).map((v) => v.split(' ').slice(0, 2).join(' ')).sort())
    .toEqual(['script-src-attr inline', 'script-src-elem https://lab.invalid/injected.js', 'script-src-elem inline']);
  expect(await page.evaluate(() => window.injected)).toBeUndefined();
}

/** Console errors the injection itself causes (the fixture lets these through, and no others). */
export const INJECTION_ERRORS = /(Executing inline script|Executing inline event handler|Loading the script 'https:\/\/lab\.invalid\/injected\.js') violates the following Content Security Policy/;
