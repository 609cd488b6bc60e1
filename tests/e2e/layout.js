// Layout read from a page: what a phone or tablet must not show (elements wider than the screen
// outside a box that scrolls, overlay labels cut by their box or running off the screen), and the
// place the lecture page keeps for a panel against the panel's height once mounted.

/** Each problem in words; [] when the page fits. */
export const layoutProblems = (page) => page.evaluate(() => {
  const width = document.documentElement.clientWidth;
  const problems = [];
  if (document.documentElement.scrollWidth > width) problems.push(`the page is ${document.documentElement.scrollWidth} px wide on a ${width} px screen`);
  const labels = '.stage-labels span, .twin-stage-labels span, .nm-cap, .rw-medium, .legend, .sphere-switch button, .toolbar button, .trace-toggle';
  for (const e of document.querySelectorAll(labels)) {
    const box = e.getBoundingClientRect();
    if (!box.width) continue; // not shown
    const name = `${e.className || e.tagName} “${e.textContent.trim().slice(0, 30)}”`;
    if (e.scrollWidth > e.clientWidth + 1) problems.push(`${name} is cut (${e.scrollWidth} px of text in ${e.clientWidth})`);
    if (box.left < -1 || box.right > width + 1) problems.push(`${name} runs off the screen (${Math.round(box.left)}–${Math.round(box.right)})`);
  }
  return problems;
});

/** The place the lecture page keeps for panel `id` before it mounts (panelPlaces.css), in px. */
export const reservedHeight = (page, id) => page.evaluate((pid) => parseFloat(getComputedStyle(document.querySelector(`#${pid} > .panel-mount`)).minHeight), id);

/** A mounted panel's own height: from the top of its mount to the bottom of its description. */
export const mountedHeight = (page, id) => page.evaluate((pid) => {
  const mount = document.querySelector(`#${pid} > .panel-mount`);
  return mount.querySelector('.panel-description').getBoundingClientRect().bottom - mount.getBoundingClientRect().top;
}, id);
