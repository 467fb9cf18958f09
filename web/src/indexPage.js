// The index page: the course's lessons with their summary, length and the progress kept
// in this browser.
import { el } from './dom.js';
import { header } from './header.js';
import { pick, t } from './words.js';
import { loadProgress } from './store.js';

export function renderIndex(root, course) {
  const items = course.lessons.map((lesson) => {
    const seen = loadProgress(lesson.id).seen.length;
    return el('li', { class: 'lesson' },
      el('h2', {}, el('a', { href: lesson.page, text: pick(lesson.title) })),
      el('p', { class: 'summary', text: pick(lesson.summary) }),
      el('p', { class: 'facts' },
        el('span', { text: t('web.steps', { count: lesson.steps }) }),
        lesson.minutes ? el('span', { text: t('web.minutes', { minutes: lesson.minutes }) }) : null,
        el('span', { class: 'progress-text', text: t('web.progress', { done: seen, total: lesson.steps }) }),
        el('progress', { max: lesson.steps, value: seen, 'aria-hidden': 'true' })));
  });
  document.title = t('web.course_title');
  root.replaceChildren(
    header(course, null, () => renderIndex(root, course)),
    el('main', {},
      el('h1', { text: t('web.course_title') }),
      el('h2', { class: 'list-title', text: t('web.lessons') }),
      el('ol', { class: 'lessons' }, ...items)));
}
