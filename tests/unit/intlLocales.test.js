// Every locale Intl is given in src comes through src/ui/safeLocale.js: eslint.config.js says so,
// and this test runs that rule with the unit tests, which CI runs (npm test does not lint).
import { describe, it, expect } from 'vitest';
import { ESLint } from 'eslint';

const eslint = new ESLint({ cwd: process.cwd() });
const localeUses = (results) => results.flatMap((r) => r.messages
  .filter((m) => m.ruleId === 'no-restricted-syntax' && /safeLocale\.js/.test(m.message))
  .map((m) => `${r.filePath.replace(`${process.cwd()}/`, '')}:${m.line}`));

describe('locales given to Intl', () => {
  it('every Intl constructor, toLocale…String and localeCompare in src takes a safe locale', async () => {
    expect(localeUses(await eslint.lintFiles(['src/**/*.js']))).toEqual([]);
  }, 60_000);

  it('the rule names a locale from anywhere else or none, in a panel and outside, and passes the safe ones', async () => {
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
      const lines = localeUses(await eslint.lintText(code, { filePath })).map((where) => where.split(':').at(-1));
      expect(lines, filePath).toEqual(['2', '3', '4', '5', '6']);
    }
  });
});
