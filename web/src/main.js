// RayLab's web page: the bundle defines window.RayLabSite; the data scripts after it
// (course.js, lessons/<id>.js) call RayLabSite.course({...}) and RayLabSite.lesson({...});
// once the document is parsed the page is drawn into #raylab-app (doc/web-data.md).
import './style.css';
import { renderIndex } from './indexPage.js';
import { startLesson } from './lessonPage.js';
import { initWords } from './words.js';

// Milliseconds since navigation start, read by the browser test (reported, never asserted).
window.raylabTimings = { bundleStart: performance.now() };
// The stylesheet lies beside the bundle; link it unless the page already does.
const bundle = document.currentScript;
if (bundle && !document.querySelector('link[href$="raylab-web.css"]')) {
  document.head.append(Object.assign(document.createElement('link'),
    { rel: 'stylesheet', href: bundle.src.replace(/\.js(\?.*)?$/, '.css') }));
}
const data = { course: null, lesson: null };
window.RayLabSite = {
  course(course) { data.course = course; },
  lesson(lesson) { data.lesson = lesson; },
};

function start() {
  const root = document.getElementById('raylab-app');
  if (!root || !data.course) return;
  window.raylabTimings.start = performance.now();
  initWords(data.course);
  if (root.dataset.page === 'lesson' && data.lesson) startLesson(root, data.course, data.lesson);
  else renderIndex(root, data.course);
}

if (document.readyState === 'loading') document.addEventListener('DOMContentLoaded', start);
else start();
