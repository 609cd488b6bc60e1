// A schema with every kind of value, an index and two keys with the older names a link may still use.
export const schema = {
  nI: { type: 'number', default: 1, min: 1, max: 3, step: 0.001, aliases: ['n1'] },
  nT: { type: 'number', default: 1.5, min: 1, max: 3, step: 0.001, aliases: ['n2'] },
  count: { type: 'number', default: 4, min: 1, max: 16, step: 1, integer: true },
  method: { type: 'enum', default: 'exact', options: ['exact', 'schlick'] },
  tint: { type: 'color', default: '#ffffff' },
  spin: { type: 'boolean', default: false },
  note: { type: 'text', default: '', maxLength: 8 },
};

/** Its defaults, written out (not read from the schema by the code under test). */
export const start = { nI: 1, nT: 1.5, count: 4, method: 'exact', tint: '#ffffff', spin: false, note: '' };
