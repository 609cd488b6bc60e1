// @ts-check
// A panel's `place` (src/panels/manifest.js) from the heights it has once mounted on the lecture
// page, measured per layout (scripts/measurePlaces.js): about 92 % of the smallest, so that a panel a
// little shorter in another browser or window of the same layout still fills what was kept; the
// browser tests (loading.spec.js, a11y.spec.js) fail a place taller than the mounted panel or under
// 40 % of it.

export const PLACE_SHARE = 0.92;
export const PLACE_LEAST = 0.4;

/**
 * The place to write in the manifest: per layout, PLACE_SHARE of its smallest height rounded down to
 * 10 px; a layout with no height keeps `current`'s value.
 * @param {Record<string, number[]>} heights  mounted heights in px, by layout (narrow, wide, widest)
 * @param {Record<string, number>} current    the entry's place now
 * @returns {Record<string, number>}
 */
export function placeFromHeights(heights, current) {
  return Object.fromEntries(Object.entries(current).map(([layout, now]) => {
    const measured = heights[layout] ?? [];
    return [layout, measured.length ? Math.floor((PLACE_SHARE * Math.min(...measured)) / 10) * 10 : now];
  }));
}

/**
 * What the browser tests would say of `place` against these heights: each problem in words.
 * @param {Record<string, number>} place
 * @param {Record<string, number[]>} heights
 * @returns {string[]}
 */
export function placeProblems(place, heights) {
  return Object.entries(heights).flatMap(([layout, measured]) => measured.flatMap((height) => {
    if (place[layout] > height) return [`${layout} ${place[layout]} is taller than the mounted ${height}`];
    if (place[layout] <= PLACE_LEAST * height) return [`${layout} ${place[layout]} is no more than 40 % of the mounted ${height}`];
    return [];
  }));
}

/** The entry's place as the manifest writes it. */
export const placeLine = (place) => `place: { ${Object.entries(place).map(([layout, px]) => `${layout}: ${px}`).join(', ')} },`;
