// The controls beside the 3D view: the legend (kinds named in words next to a swatch), and
// the depth slider that reveals the tree depth by depth while the narration up to that
// depth is read out (aria-live), like the window's bounce animation.
import { el } from './dom.js';
import { pick, t } from './words.js';

export function legendList(legend) {
  return el('section', { class: 'legend' }, el('h3', { text: t('web.legend') }),
    el('ul', {}, ...legend.map((entry) => el('li', {},
      el('span', { class: 'swatch', 'aria-hidden': 'true',
        style: `background: rgb(${entry.color.map((c) => Math.round(255 * c)).join(',')})` }),
      el('span', { text: pick(entry.label) })))));
}

/// The slider 0..maxDepth (start: revealDepth or the whole tree) and the narration lines.
export function depthControl(view3d, narration, show) {
  const max = view3d.maxDepth;
  const start = view3d.revealDepth ?? max;
  const slider = el('input', { type: 'range', id: 'depth', min: 0, max, step: 1, value: start });
  const value = el('output', { for: 'depth' });
  const lines = el('ol', { class: 'narration-lines' });
  const live = el('p', { class: 'narration-live', 'aria-live': 'polite' });
  const update = (announce) => {
    const depth = Number(slider.value);
    value.textContent = depth === max ? `${depth} (${t('web.depth_all')})` : String(depth);
    const shown = narration.filter((line) => line.depth <= depth);
    lines.replaceChildren(...shown.map((line) => el('li', { text: pick(line.text) })));
    if (announce) live.textContent = shown.filter((line) => line.depth === depth).map((line) => pick(line.text)).join(' ');
    show(depth);
  };
  slider.addEventListener('input', () => update(true));
  update(false);
  return el('section', { class: 'depth' },
    el('label', { for: 'depth', text: `${t('web.depth')}: ` }), slider, value,
    narration.length ? el('h3', { text: t('web.narration') }) : null, lines, live);
}
