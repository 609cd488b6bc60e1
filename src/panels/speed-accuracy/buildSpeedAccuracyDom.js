// The DOM of the speed-accuracy panel: the recommendation, a line about the error source (shown
// while the GPU read-back runs or after it failed), the chart host, the benchmark bar (run,
// cancel, progress, JSON export), the device line and the per-method table.
import { button, el } from '../../ui/el.js';
import { toDegrees } from '../../optics/angles.js';
import { makeScrollBox } from '../../ui/scrollBox.js';
import { angle, sci, tickLabel } from '../../ui/format.js';
import { formatCodes } from './formatMeasures.js';
import english from 'virtual:messages/en/speed-accuracy';
import { messages } from '../../i18n/messages.js';

const t = messages('speed-accuracy', english);

/** A number as short as it is (0.5, 12.75), with the page's decimal separator. */
const plain = (v) => tickLabel(v, 1e-6);

export function buildSpeedAccuracyDom(host, { onRun, onCancel, onJson }) {
  const root = el('div', 'sa-panel');
  const advice = el('div', 'sa-advice');
  advice.setAttribute('aria-live', 'polite');
  const pick = el('p', 'sa-pick');
  const reason = el('p', 'sa-reason');
  const criterion = el('p', 'sa-criterion');
  advice.append(pick, reason, criterion);

  const source = el('p', 'sa-source');
  source.setAttribute('role', 'status');
  source.hidden = true;

  const chartHost = el('div', 'sa-chart-host');
  const legend = el('p', 'sa-legend', t('legend'));

  const bench = el('div', 'sa-bench');
  const run = button(t('run'), 'sa-run');
  const cancel = button(t('cancel'), 'sa-cancel');
  cancel.disabled = true;
  const progress = el('progress', 'sa-progress');
  progress.max = 1;
  progress.value = 0;
  progress.setAttribute('aria-label', t('progress'));
  const status = el('span', 'sa-status');
  status.setAttribute('role', 'status');
  const json = button(t('exportJson'), 'sa-json');
  bench.append(run, cancel, progress, status, json);
  run.addEventListener('click', onRun);
  cancel.addEventListener('click', onCancel);
  json.addEventListener('click', onJson);

  const device = el('p', 'sa-device');
  const table = el('table', 'sa-table');
  const caption = el('caption');
  const thead = el('thead');
  const tbody = el('tbody');
  table.append(caption, thead, tbody);
  const tableWrap = makeScrollBox(el('div', 'sa-table-wrap'), t('tableOfMethods'));
  tableWrap.append(table);
  const stage = el('div', 'sa-stage'); // off-screen: the frame-timing canvases live here while they run
  stage.setAttribute('aria-hidden', 'true');

  root.append(advice, source, chartHost, legend, bench, device, tableWrap, stage);
  host.append(root);

  return {
    chartHost,
    stage,
    /** pickBefore and pickAfter: the pick's sentence on either side of the method's name (label). */
    setAdvice({ label, pickBefore, pickAfter, reasonText, criterionText }) {
      pick.replaceChildren(el('span', 'sa-pick-scene', pickBefore), el('strong', 'sa-pick-method', label), pickAfter);
      reason.textContent = reasonText;
      criterion.textContent = criterionText;
    },
    /** A line about the error source; warning: styled as one. Empty text hides it. */
    setSource(text, warning = false) {
      source.textContent = text;
      source.hidden = !text;
      source.classList.toggle('sa-source-warning', warning);
    },
    setRunning(running) {
      run.disabled = running;
      cancel.disabled = !running;
      if (!running) progress.value = 0;
    },
    setProgress(fraction, label) {
      progress.value = Math.min(1, Math.max(0, fraction));
      status.textContent = label;
    },
    setStatus(text) {
      status.textContent = text;
    },
    setDevice(text) {
      device.textContent = text;
    },
    /** rows: recommend()'s table plus { meanCodes, costText, caseText, onFront, recommended }. */
    setTable(rows, { costHeader, captionText, budgetCodes }) {
      caption.textContent = captionText;
      const head = el('tr');
      const after = ['columnWorst', 'columnWhere', 'columnAverage', 'columnMaxError', 'columnVerdict'].map((key) => t(key));
      for (const h of [t('columnMethod'), costHeader, ...after]) {
        const th = el('th', '', h);
        th.scope = 'col';
        head.append(th);
      }
      thead.replaceChildren(head);
      tbody.replaceChildren(...rows.map((r) => {
        const tr = el('tr', r.recommended ? 'sa-recommended' : '');
        const name = el('th', '', r.label);
        name.scope = 'row';
        const where = r.nanCount > 0 ? t('whereNotFinite', { count: r.nanCount, shown: String(r.nanCount) })
          : r.thetaAtMax === null ? '–' : t('whereAt', { angle: angle(toDegrees(r.thetaAtMax), 1), case: r.caseText });
        const budget = { count: budgetCodes, codes: plain(budgetCodes) };
        const within = t(r.passes ? 'verdictWithin' : 'verdictOver', budget);
        const verdict = r.onFront ? t('verdictOnFront', { verdict: within }) : within;
        const max = Number.isFinite(r.max) ? sci(r.max, 2) : t('notFinite');
        const cells = [r.costText, formatCodes(r.maxCodes), where, formatCodes(r.meanCodes), max, verdict];
        tr.append(name, ...cells.map((t) => el('td', '', t)));
        return tr;
      }));
    },
  };
}
