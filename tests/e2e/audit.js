// The accessibility audit the browser tests share: axe-core, failing on any serious or critical
// violation, with the visible-label rule (label-content-name-mismatch, still marked experimental in
// axe) on, since a voice-control user says what the control shows.
import AxeBuilder from '@axe-core/playwright';

const EXTRA_RULES = { 'label-content-name-mismatch': { enabled: true }, 'td-has-header': { enabled: true } };

/** The serious and critical violations on the page, each with the first elements it names. */
export async function seriousViolations(page) {
  const { violations } = await new AxeBuilder({ page }).options({ rules: EXTRA_RULES, resultTypes: ['violations'] }).analyze();
  return violations
    .filter((v) => v.impact === 'serious' || v.impact === 'critical')
    .map((v) => `${v.impact} ${v.id}: ${v.help} (${v.nodes.slice(0, 3).map((n) => n.target.join(' ')).join('; ')})`);
}
