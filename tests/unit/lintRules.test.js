// The lint rules of eslint.config.js say what they should: each is tried on a small piece of code
// here (npm run lint runs them over the sources; npm test runs lint).
import { describe, it, expect } from 'vitest';
import { ESLint } from 'eslint';

const eslint = new ESLint({ cwd: process.cwd() });
/** The lines of `code` (as filePath) that `rule` names, those whose message matches `about`. */
async function flagged(code, filePath, rule, about = /./) {
  const [result] = await eslint.lintText(code, { filePath });
  return result.messages.filter((m) => m.ruleId === rule && about.test(m.message)).map((m) => m.line);
}

describe('lint rules', () => {
  it('a panel formats a shown number through src/ui/format.js, never .toFixed; src/ui may', async () => {
    const code = 'export const a = (x) => `${x.toFixed(2)}°`;\nexport const b = (x) => x?.toFixed(1);\n';
    expect(await flagged(code, 'src/panels/schlick/probe.js', 'no-restricted-syntax', /format\.js/)).toEqual([1, 2]);
    expect(await flagged(code, 'src/ui/probe.js', 'no-restricted-syntax', /format\.js/)).toEqual([]);
  });

  it('Intl gets its locale through src/ui/safeLocale.js, in a panel and outside', async () => {
    const code = [
      "import { FALLBACK_LOCALE, pageLocale, safeLocale } from '../ui/safeLocale.js';",
      'export const a = new Intl.NumberFormat(navigator.language);',
      'export const b = Intl.DateTimeFormat();',
      'export const c = (d) => d.toLocaleString();',
      "export const d = (d) => d.toLocaleDateString('en_US');",
      'export const e = (x, y) => x.localeCompare(y);',
      'export const f = new Intl.Collator(pageLocale(), { numeric: true });',
      "export const g = (d) => d.toLocaleTimeString(safeLocale('de_DE'));",
      'export const h = (x, y) => x.localeCompare(y, FALLBACK_LOCALE);',
      "export const i = Intl.getCanonicalLocales('en');",
    ].join('\n');
    for (const filePath of ['src/homework/probe.js', 'src/panels/schlick/probe.js']) {
      expect(await flagged(code, filePath, 'no-restricted-syntax', /safeLocale\.js/), filePath).toEqual([2, 3, 4, 5, 6]);
    }
  });

  it('own, isObject and the embed link have one home each (src/host/own.js, src/host/embedLink.js)', async () => {
    const code = [
      'export const own = (o, k) => (Object.hasOwn(o, k) ? o[k] : undefined);',
      'export function isObject(v) { return typeof v === "object"; }',
      'export const field = (o, k) => Reflect.get(o, k);',
      "export const link = (u) => { u.searchParams.set('panel', 'schlick'); return u; };",
      "export const query = new URLSearchParams({ panel: 'schlick' });",
      'export const kept = [1, 2].filter((own) => own > 1);',
      "export const set = (m) => m.set('theme', 'dark');",
    ].join('\n');
    for (const filePath of ['src/homework/probe.js', 'src/panels/schlick/probe.js']) {
      expect(await flagged(code, filePath, 'no-restricted-syntax', /own\.js|embedLink\.js/), filePath).toEqual([1, 2, 3, 4, 5]);
    }
    expect(await flagged(code, 'src/host/own.js', 'no-restricted-syntax', /own\.js|embedLink\.js/)).toEqual([]);
  });

  it('no line of src is longer than 140 characters', async () => {
    const code = `export const a = '${'x'.repeat(120)}';\nexport const b = '${'y'.repeat(130)}';\n`;
    expect(await flagged(code, 'src/ui/probe.js', 'max-len')).toEqual([2]);
  });
});
