// Rows of the refractive-index table: each dielectric of materials.js seen from air (n = 1),
// plus an optional custom index, and a stable sort by any column. Pure data, no DOM; a row's name
// and source are the words the table shows, in the page's language (the catalogue's).
import { toDegrees } from '../../optics/angles.js';
import { dielectrics, dielectricSummary } from '../../optics/materials.js';
import { SPEED_OF_LIGHT_KM_S } from '../../optics/waves.js';
import { FALLBACK_LOCALE } from '../../ui/safeLocale.js';
import { materialName } from '../shared/materialName.js';
import english from 'virtual:messages/en/refractive-index';
import { messages } from '../../i18n/messages.js';

const t = messages('refractive-index', english);
const sourceKey = (id) => `source.${id.replace(/-([a-z])/g, (_, letter) => letter.toUpperCase())}`;

export const SORT_KEYS = ['name', 'n', 'speed', 'r0', 'critical', 'source'];

/**
 * One table row: n, phase speed c/n (fraction of c and km/s), group speed c/n_g in km/s (null
 * without dispersion data), R0 from air, critical angle to air (degrees). name and source: as shown
 * (given, or the catalogue's for a material of materials.json).
 */
export function materialRow(material, { name = materialName(material.id), source = t(sourceKey(material.id)) } = {}) {
  const s = dielectricSummary(material);
  return {
    id: s.id,
    name,
    n: s.n,
    source,
    speed: s.speed,
    speedKmS: SPEED_OF_LIGHT_KM_S * s.speed,
    groupSpeedKmS: s.groupSpeed === null ? null : SPEED_OF_LIGHT_KM_S * s.groupSpeed,
    r0: s.r0,
    critical: s.criticalAngle === null ? null : toDegrees(s.criticalAngle),
  };
}

export function materialRows() {
  return dielectrics.map(materialRow);
}

/** The row for a custom index (id 'custom'). */
export function customRow(n) {
  return materialRow({ id: 'custom', n }, { name: t('custom'), source: t('customSource') });
}

/**
 * A sorted copy. Text sorts alphabetically; numbers numerically; a missing value (no critical
 * angle) goes last either way; ties keep the data's order.
 */
export function sortMaterialRows(rows, key, direction = 'asc') {
  if (!SORT_KEYS.includes(key)) throw new RangeError(`cannot sort by ${key}`);
  const sign = direction === 'desc' ? -1 : 1;
  return rows
    .map((row, index) => ({ row, index }))
    .sort((a, b) => {
      const x = a.row[key];
      const y = b.row[key];
      if (x === null || y === null) return x === y ? a.index - b.index : x === null ? 1 : -1;
      const order = typeof x === 'string' ? x.localeCompare(y, FALLBACK_LOCALE) : x - y;
      return order !== 0 ? sign * order : a.index - b.index;
    })
    .map(({ row }) => row);
}
