// uPlot 1.6.32 builds a number formatter for navigator.language when its module is evaluated, and
// Intl refuses what Linux browsers report under LANG=C.UTF-8 (`en-US@posix`): every panel with a
// plot then failed to load. patches/uplot+1.6.32.patch (applied by `npm ci`, through patch-package)
// makes it use the implicit locale, as upstream did after that release. This loads uPlot as a
// browser with that language would.
import { afterEach, describe, expect, it, vi } from 'vitest';

afterEach(() => {
  vi.unstubAllGlobals();
  vi.resetModules();
});

/** Just what uPlot touches when its module is evaluated. */
function browserReporting(language) {
  const matchMedia = () => ({ matches: false, addEventListener() {}, removeEventListener() {} });
  vi.stubGlobal('window', new EventTarget());
  vi.stubGlobal('devicePixelRatio', 1);
  vi.stubGlobal('matchMedia', matchMedia);
  vi.stubGlobal('document', {});
  vi.stubGlobal('navigator', { language, languages: [language] });
}

describe('uPlot under a language Intl refuses', () => {
  it.each(['en-US@posix', 'C', ''])('loads and formats under %j', async (language) => {
    browserReporting(language);
    const { default: uPlot } = await import('uplot');
    expect(typeof uPlot).toBe('function');
    expect(uPlot.fmtNum(0.5)).toMatch(/^0[.,]5$/);
  });
});
