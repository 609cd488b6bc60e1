// @ts-check
// Panel `refractive-index`: the dielectrics of src/optics/materials.js in a sortable table (n,
// speed c/n, R0 from air, critical angle to air, source), plus a live "Custom" row. "Use" applies
// a material's n to every panel of the page. Rows come from src/panels/refractive-index/materialRows.js.
import { customRow, materialRows, sortMaterialRows } from './materialRows.js';
import { buildIndexTable } from './buildIndexTable.js';
import { angle, fixed } from '../../ui/format.js';
import './styles.css';
import { schema } from './schema.js';
import { indexText } from '../shared/indexText.js';
import english from 'virtual:messages/en/refractive-index';
import { messages } from '../../i18n/messages.js';

const t = messages('refractive-index', english);

export { schema };

/**
 * @param {HTMLElement} root
 * @param {import('../../host/panelContract.js').PanelContext<typeof schema>} ctx
 * @returns {import('../../host/panelContract.js').PanelInstance}
 */
export function mount(root, ctx) {
  const { values } = ctx;
  const rows = materialRows();
  let custom = customRow(values.customN);
  let shown = [];

  // Choosing a row applies it to every panel of the page; the page-wide material marks its row
  // here in turn (the manifest's materialSelect).
  function choose(row) {
    ctx.set({ selected: row.id });
    ctx.applyMaterial({ id: row.id, name: row.name, n: row.n });
  }

  const table = buildIndexTable(root, {
    onSort(key) {
      ctx.set(values.sort === key ? { dir: values.dir === 'asc' ? 'desc' : 'asc' } : { sort: key, dir: 'asc' });
    },
    onUse: choose,
  });

  ctx.bind(ctx.gui.addFolder(t('folder')), ['customN', 'sort', 'dir']);

  function update(keys = []) {
    custom = customRow(values.customN);
    shown = sortMaterialRows(rows, values.sort, values.dir);
    table.render(shown, custom, { sort: values.sort, dir: values.dir, selected: values.selected });
    // A custom material in use follows its control live.
    if (keys.includes('customN') && values.selected === 'custom') {
      ctx.applyMaterial({ id: 'custom', name: custom.name, n: values.customN });
    }
  }
  update();

  const selectedRow = () => (values.selected === 'custom' ? custom : rows.find((r) => r.id === values.selected));

  return {
    table,
    get rows() { return shown; },
    update,
    describe() {
      const byN = sortMaterialRows(rows, 'n', 'asc');
      const lo = byN[0];
      const hi = byN[byN.length - 1];
      const chosen = selectedRow();
      return t('describe', {
        count: String(rows.length), loN: indexText(lo.n), loName: lo.name, hiN: indexText(hi.n), hiName: hi.name,
        hiR0: fixed(hi.r0, 3), hiCritical: angle(hi.critical, 1),
        chosen: chosen ? 'yes' : 'no', name: chosen?.name ?? '', n: chosen ? indexText(chosen.n) : '',
        r0: chosen ? fixed(chosen.r0, 3) : '',
      });
    },
    csv() {
      const all = [...shown, custom];
      return {
        filename: 'refractive-index.csv',
        columns: {
          material: all.map((r) => r.id),
          n_589nm: all.map((r) => r.n),
          speed_fraction_of_c: all.map((r) => r.speed),
          speed_km_per_s: all.map((r) => r.speedKmS),
          group_speed_km_per_s: all.map((r) => (r.groupSpeedKmS === null ? NaN : r.groupSpeedKmS)),
          R0_from_air: all.map((r) => r.r0),
          critical_angle_deg: all.map((r) => (r.critical === null ? NaN : r.critical)),
        },
      };
    },
    dispose() {
      table.dispose();
    },
  };
}
