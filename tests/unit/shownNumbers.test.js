// Every number a panel shows goes through src/ui/format.js (a real minus sign, the decimals its
// column keeps): eslint.config.js forbids .toFixed in src/panels, and this test runs that rule as
// part of the unit tests, which CI runs (npm test does not lint).
import { describe, it, expect } from 'vitest';
import { ESLint } from 'eslint';

const RULE = 'no-restricted-syntax';
const eslint = new ESLint({ cwd: process.cwd() });
const toFixedUses = (results) => results.flatMap((r) => r.messages
  .filter((m) => m.ruleId === RULE && /format\.js/.test(m.message))
  .map((m) => `${r.filePath.replace(`${process.cwd()}/`, '')}:${m.line}`));

describe('shown numbers', () => {
  it('no panel formats a number with .toFixed', async () => {
    expect(toFixedUses(await eslint.lintFiles(['src/panels/**/*.js']))).toEqual([]);
  }, 60_000);

  it('the rule names a .toFixed call or reference in a panel, and leaves src/ui alone', async () => {
    const code = 'export const a = (x) => `${x.toFixed(2)}°`;\nexport const b = (x) => x?.toFixed(1);\n';
    const inPanel = await eslint.lintText(code, { filePath: 'src/panels/schlick/probe.js' });
    expect(toFixedUses(inPanel).map((where) => where.split(':').at(-1))).toEqual(['1', '2']);
    const inUi = await eslint.lintText(code, { filePath: 'src/ui/probe.js' });
    expect(toFixedUses(inUi)).toEqual([]);
  });
});
