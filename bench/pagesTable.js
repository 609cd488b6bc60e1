// The page measurements of npm run bench as text: the lines it prints, and the table of bench/RESULTS.md.
const ms = ({ median, min, max }) => `${median.toFixed(0)} [${min.toFixed(0)}, ${max.toFixed(0)}]`;
const ratio = ({ median, min, max }) => `${median.toFixed(2)} [${min.toFixed(2)}, ${max.toFixed(2)}]`;
const kb = (bytes) => `${(bytes / 1024).toFixed(0)} KB`;

export function pagesTable(pages) {
  const { hero, panels, loads, layoutShift, classView, lighthouse } = pages;
  const lines = [
    `Hero embed ${hero.width}×${hero.height} vs three.js peer, ms per update (runs of ${hero.updates} set → rendered), median [min, max] over ${hero.rounds} interleaved rounds:`,
    `  hero ${ms(hero.hero.msPerUpdate)}, peer ${ms(hero.peer.msPerUpdate)}, hero/peer ${hero.ratio.toFixed(2)} `
      + `(per round ${hero.ratioPerRound.map((r) => r.toFixed(2)).join(', ')})`,
    ...(hero.plainPeer ? [`  peer without clear coat ${ms(hero.plainPeer.msPerUpdate)}, hero/plain peer ${hero.plainRatio.toFixed(2)} `
      + `(per round ${hero.plainRatioPerRound.map((r) => r.toFixed(2)).join(', ')})`] : []),
    `WebGL panels in a ${panels.width}×${panels.height} embed, ms per update and its ratio to the hero's in the same round, `
      + `median [min, max] over ${panels.runs ?? 3} interleaved rounds:`,
    ...Object.entries(panels.panels).map(([id, p]) => `  ${id.padEnd(18)} ${ms(p.msPerUpdate)} (${p.key})`
      + (p.toHero && id !== 'spheres' ? `  ×hero ${ratio(p.toHero)}` : '')),
    `Lecture page: first frame of the hero ${(loads.lecture.firstFrameMs ?? NaN).toFixed(0)} ms after navigation, `
      + `${kb(loads.lecture.jsGzipBeforeFirstFrame)} of gzipped JS before it (budget 96.8 KB, held by tests/e2e/loading.spec.js), `
      + `${kb(loads.lecture.jsGzipBeforeReady)} before ready`,
    'Embeds: first frame (ms), gzipped JS until ready:',
    ...Object.entries(loads.embeds).map(([id, e]) => `  ${id.padEnd(18)} ${(e.firstFrameMs ?? NaN).toFixed(0).padStart(6)} ms  ${kb(e.jsGzipBeforeReady)}`),
  ];
  if (layoutShift) lines.push(`Layout shift over a full scroll of the lecture page: ${layoutShift.total.toFixed(3)} (${layoutShift.shifts} shifts, largest ${layoutShift.largest.toFixed(3)})`);
  if (classView) {
    const line = (c) => `${ms(c.wallMs)} ms over ${c.runs} run${c.runs === 1 ? '' : 's'} (graded in ${c.where}), longest task on the page's thread ${c.longestTaskMs.toFixed(0)} ms `
      + `(script ${c.longestScriptTaskMs.toFixed(0)}, a frame's rendering ${c.longestRenderMs.toFixed(0)})`;
    lines.push(`Grade a class, ${classView.students} hand-ins × ${classView.questions} questions, from the zip to the whole gradebook, median [min, max]: ${line(classView)}; `
      + `${classView.rows} rows, ${classView.elementsPerStudent.toFixed(0)} elements per student (a row has ${classView.elementsPerRow.toFixed(0)})`);
    if (classView.codes) lines.push(`  from pasted codes: ${line(classView.codes)}`);
  }
  if (lighthouse) {
    lines.push(`Lighthouse ${lighthouse.version} (${lighthouse.preset}) on the lecture page, median [min, max] of ${lighthouse.runs}: performance ${ms(lighthouse.score)}, `
      + `total blocking time ${ms(lighthouse.totalBlockingTimeMs)} ms, layout shift ${lighthouse.cumulativeLayoutShift.median.toFixed(3)}, `
      + `LCP ${ms(lighthouse.largestContentfulPaintMs)} ms`);
  }
  return lines.join('\n');
}
