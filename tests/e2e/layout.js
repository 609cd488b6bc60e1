// What a phone or tablet must not show: elements wider than the screen outside a box that scrolls,
// and overlay labels cut by their box or running off the screen.

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
