// What the page keeps in this browser (localStorage): the language, and per lesson the steps
// seen, the current step and the answers. Pages opened from file:// share one storage, so
// every key starts with "raylab.". Storage can be off (private mode): then nothing is kept.
const prefix = 'raylab.';

function read(key, fallback) {
  try {
    const text = window.localStorage.getItem(prefix + key);
    return text === null ? fallback : JSON.parse(text);
  } catch (error) {
    return fallback;
  }
}

function write(key, value) {
  try {
    window.localStorage.setItem(prefix + key, JSON.stringify(value));
  } catch (error) {
    // Storage full or disabled: the page works, it only forgets.
  }
}

export function loadLanguage() {
  return read('language', null);
}

export function saveLanguage(lang) {
  write('language', lang);
}

/// A lesson's progress: { step, seen: [indices], answers: { [index]: Answer } } where
/// Answer = { tries, correct, firstTry, revealed, value }.
export function loadProgress(lessonId) {
  const progress = read(`lesson.${lessonId}`, {});
  return {
    step: Number.isInteger(progress.step) ? progress.step : 0,
    seen: Array.isArray(progress.seen) ? progress.seen : [],
    answers: progress.answers && typeof progress.answers === 'object' ? progress.answers : {},
  };
}

export function saveProgress(lessonId, progress) {
  write(`lesson.${lessonId}`, progress);
}

/// Forgets every answer and all progress (the language stays).
export function resetAll() {
  try {
    const keys = [];
    for (let i = 0; i < window.localStorage.length; ++i) keys.push(window.localStorage.key(i));
    for (const key of keys) if (key.startsWith(`${prefix}lesson.`)) window.localStorage.removeItem(key);
  } catch (error) {
    // Nothing kept, nothing to forget.
  }
}
