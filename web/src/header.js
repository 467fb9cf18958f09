// The bar on top of every page: the way back, the language switch (en / 中文) and the reset
// button. The switch re-renders the page in place; nothing is reloaded.
import { el } from './dom.js';
import { currentLanguage, languageName, setLanguage, t } from './words.js';
import { resetAll } from './store.js';

export function header(course, backHref, rerender) {
  const switcher = el('div', { class: 'languages', role: 'group', 'aria-label': t('web.language') },
    ...course.languages.map((lang) => el('button', {
      type: 'button', lang: lang === 'zh' ? 'zh-CN' : lang, 'aria-pressed': lang === currentLanguage() ? 'true' : 'false',
      'data-lang': lang, text: languageName(lang),
      onclick: () => { setLanguage(lang); rerender(); document.querySelector(`[data-lang="${lang}"]`)?.focus(); },
    })));
  const reset = el('button', { type: 'button', class: 'reset', text: t('web.reset'),
    onclick: () => {
      if (window.confirm(t('web.reset_confirm'))) { resetAll(); rerender(); }
    } });
  return el('header', { class: 'top' },
    backHref ? el('a', { href: backHref, class: 'back', text: t('web.back') }) : el('span', { class: 'brand', text: t('web.course_title') }),
    el('div', { class: 'tools' }, switcher, reset));
}
