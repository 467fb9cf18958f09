// The page's words: every word it shows comes from course.phrases (the phrase table's "web.*"
// keys) or from the lesson's own {en, zh} texts; this file holds no words itself.
import { loadLanguage, saveLanguage } from './store.js';

let course = null;
let language = 'en';

/// Chooses the language: the one kept in this browser if the site has it, else the default.
export function initWords(theCourse) {
  course = theCourse;
  const kept = loadLanguage();
  language = course.languages.includes(kept) ? kept : course.defaultLanguage;
  document.documentElement.lang = htmlLang(language);
}

export function currentLanguage() {
  return language;
}

export function setLanguage(lang) {
  language = lang;
  saveLanguage(lang);
  document.documentElement.lang = htmlLang(lang);
}

function htmlLang(lang) {
  return lang === 'zh' ? 'zh-CN' : lang;
}

/// A {en, zh} text in the current language, falling back to any language that has one.
export function pick(text) {
  if (!text) return '';
  if (typeof text === 'string') return text;
  if (text[language]) return text[language];
  for (const lang of course.languages) if (text[lang]) return text[lang];
  return '';
}

/// A UI phrase by key with {name} placeholders filled; a missing phrase shows its key so
/// the gap is visible (and the browser test, which looks for "web." in the page, fails).
export function t(key, values = {}) {
  const phrase = course.phrases[key];
  const text = phrase ? pick(phrase) : key;
  return text.replace(/\{(\w+)\}/g, (whole, name) => (name in values ? String(values[name]) : whole));
}

/// Whether the course has a phrase (optional words such as a language's own name).
export function hasPhrase(key) {
  return Boolean(course.phrases[key]);
}

/// The name of a language written in that language ("English", "中文"), from the phrase
/// "web.language_name"; the language code when the site lacks it.
export function languageName(lang) {
  const phrase = course.phrases['web.language_name'];
  return (phrase && phrase[lang]) || lang;
}
