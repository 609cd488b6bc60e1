// The material table's columns, by key, in order (their headings are the catalogue's): a module of
// its own so that the panel's schema, which sorts by one of them, needs nothing of the table's DOM.
export const COLUMN_KEYS = Object.freeze(['name', 'n', 'speed', 'r0', 'critical', 'source']);
