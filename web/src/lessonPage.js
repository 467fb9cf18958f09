// The lesson page: the step list, and the current step as the window stages it: title, text,
// teacher's notes, pictures, the live 3D view with its legend, the depth slider with the
// narration, the question. ←/→ move between steps (unless typing or in the 3D view).
import { el, paragraphs } from './dom.js';
import { header } from './header.js';
import { questionSection } from './question.js';
import { loadProgress, saveProgress } from './store.js';
import { createView, webglAvailable } from './view3d.js';
import { pick, t } from './words.js';
import { depthControl, legendList } from './treeControls.js';

export function startLesson(root, course, lesson) {
  const page = { root, course, lesson, progress: loadProgress(lesson.id), view: null };
  page.progress.step = Math.min(Math.max(page.progress.step, 0), lesson.steps.length - 1);
  document.addEventListener('keydown', (event) => {
    const target = event.target;
    if (event.altKey || event.ctrlKey || event.metaKey || target.closest('input, textarea, select, .view')) return;
    if (event.key === 'ArrowLeft') goTo(page, page.progress.step - 1);
    if (event.key === 'ArrowRight') goTo(page, page.progress.step + 1);
  });
  render(page);
}

function goTo(page, index) {
  if (index < 0 || index >= page.lesson.steps.length) return;
  page.progress.step = index;
  render(page);
  page.root.querySelector('#step-title')?.focus();
}

function answerState(page, step) {
  const key = String(step.index);
  page.progress.answers[key] ??= { tries: 0, correct: false, firstTry: false, revealed: false, value: null };
  return page.progress.answers[key];
}

function render(page) {
  const { lesson, progress } = page;
  if (!progress.seen.includes(progress.step)) progress.seen.push(progress.step);
  saveProgress(lesson.id, progress);
  page.view?.delete();
  page.view = null;
  document.title = `${pick(lesson.title)} · ${t('web.course_title')}`;
  const nav = el('nav', { class: 'steps', 'aria-label': t('web.lessons') }, el('ol', {},
    ...lesson.steps.map((step, i) => el('li', {}, el('button', {
      type: 'button', 'aria-current': i === progress.step ? 'step' : false,
      class: progress.seen.includes(i) ? 'seen' : '', text: `${i + 1}. ${pick(step.title)}`,
      onclick: () => goTo(page, i),
    })))));
  const article = el('article', { class: 'step' });
  page.root.replaceChildren(header(page.course, '../index.html', () => render(page)),
    el('div', { class: 'lesson-layout' }, nav, el('main', {}, el('h1', { text: pick(lesson.title) }), article)));
  fillStep(page, article, lesson.steps[progress.step]);
}

function fillStep(page, article, step) {
  const total = page.lesson.steps.length;
  article.append(
    el('p', { class: 'step-of', text: t('web.step_of', { n: step.index + 1, total }) }),
    el('h2', { id: 'step-title', tabindex: '-1', text: pick(step.title) }),
    paragraphs(pick(step.text), 'text'));
  if (step.notes) {
    article.append(el('aside', { class: 'notes' }, el('h3', { text: t('web.notes') }), paragraphs(pick(step.notes), 'notes-text')));
  }
  for (const picture of step.pictures) {
    article.append(el('figure', {}, el('img', { src: pick(picture.src), alt: pick(picture.alt) }),
      el('figcaption', { text: pick(picture.alt) })));
  }
  const treeBox = el('div', { class: 'tree-box' });
  article.append(treeBox);
  const state = step.question ? answerState(page, step) : null;
  fillTree(page, treeBox, step, state);
  if (pick(step.caption)) article.append(el('p', { class: 'caption', text: pick(step.caption) }));
  if (pick(step.inspector)) {
    article.append(el('section', { class: 'inspector' }, el('h3', { text: t('web.inspector') }),
      el('pre', { text: pick(step.inspector) })));
  }
  if (step.question) article.append(questionBox(page, step, state, treeBox));
  if (step.index === page.lesson.steps.length - 1) article.append(summary(page));
  article.append(el('div', { class: 'step-buttons' },
    el('button', { type: 'button', class: 'previous', disabled: step.index === 0, text: t('web.previous'),
      onclick: () => goTo(page, step.index - 1) }),
    el('button', { type: 'button', class: 'next', disabled: step.index === page.lesson.steps.length - 1,
      text: t('web.next'), onclick: () => goTo(page, step.index + 1) })));
}

function questionBox(page, step, state, treeBox) {
  const box = el('div', { class: 'question-box' });
  const draw = () => {
    box.replaceChildren(questionSection(step.question, state, () => {
      saveProgress(page.lesson.id, page.progress);
      if ((step.view3d?.hidden || step.view3d?.verdicts) && (state.tries === 1 || state.revealed)) fillTree(page, treeBox, step, state);
      draw();
      (box.querySelector('input:not([disabled])') ?? box.querySelector('.feedback')).focus?.();
    }));
    box.querySelector('.feedback').setAttribute('tabindex', '-1');
  };
  draw();
  return box;
}

/// The 3D view, legend, depth slider and narration; a predict step's tree waits for an answer.
function fillTree(page, box, step, state) {
  page.view?.delete();
  page.view = null;
  box.replaceChildren();
  if (!step.view3d) return;
  const verdicts = verdictControl(page, box, step, state);
  const view3d = verdicts.on ? withVerdicts(step.view3d) : step.view3d;
  const waiting = view3d.hidden && !(state && state.tries > 0);
  if (!webglAvailable()) {
    box.append(el('p', { class: 'note', text: t('web.webgl_missing') }));
  } else {
    const container = el('div', { class: 'view', tabindex: '0', role: 'application', 'aria-label': t('web.view3d'), title: t('web.view3d') });
    box.append(container, el('div', { class: 'view-tools' },
      el('button', { type: 'button', class: 'reset-view', text: t('web.reset_view'), onclick: () => page.view?.resetCamera() })));
    page.view = createView(container, view3d);
    container.addEventListener('keydown', (event) => viewKeys(page.view, event));
    window.raylabTimings.firstView ??= performance.now();
  }
  if (view3d.legend.length) box.append(legendList(view3d.legend));
  if (verdicts.element) box.append(verdicts.element);
  const show = (depth) => page.view?.showDepth(waiting ? -1 : depth);
  if (!waiting) box.append(depthControl(view3d, step.narration, show));
  else show(-1);
}

/// Whether a step's question is answered or its answer revealed (a step without one: always).
function answered(state) {
  return !state || state.tries > 0 || state.revealed;
}

/// A bug-hunt step's choice "colour by verdict", offered once its question is answered or
/// revealed (the verdicts show where the trees part, never which bug); before that, a note.
function verdictControl(page, box, step, state) {
  if (!step.view3d.verdicts) return { on: false, element: null };
  if (!answered(state)) return { on: false, element: el('p', { class: 'verdict-later', text: t('web.verdict_later') }) };
  page.verdictsOn ??= {};
  const on = Boolean(page.verdictsOn[step.index]);
  const toggle = el('input', { type: 'checkbox', id: 'verdicts', checked: on, onchange: () => {
    page.verdictsOn[step.index] = toggle.checked;
    fillTree(page, box, step, state);
    box.querySelector('#verdicts')?.focus();
  } });
  const element = el('section', { class: 'verdicts' },
    el('label', { for: 'verdicts' }, toggle, ` ${t('web.verdict_toggle')}`),
    on ? el('p', { class: 'verdict-note', text: t('web.verdict_note') }) : null);
  return { on, element };
}

const kReferenceGrey = [0.62, 0.62, 0.62];

/// The step's tree coloured by verdict, the correct engine's tree thin and grey beside it
/// (the depth slider reaching the deeper of the two), the legend naming the verdicts.
function withVerdicts(view3d) {
  const { verdicts } = view3d;
  const rays = view3d.rays.map((ray, i) => ({ ...ray, color: verdicts.colors[i] ?? ray.color }));
  const reference = verdicts.reference.map((ray) => ({ ...ray, id: -1 - ray.id, color: kReferenceGrey, width: 1 }));
  const label = { en: t('web.verdict_reference'), zh: t('web.verdict_reference') };
  return {
    ...view3d,
    rays: [...reference, ...rays],
    legend: [...verdicts.legend, { kind: 'reference', color: kReferenceGrey, label }],
    maxDepth: Math.max(view3d.maxDepth, ...reference.map((ray) => ray.depth)),
  };
}

/// Keyboard for the 3D view: arrows rotate, + and - zoom, 0 resets.
function viewKeys(view, event) {
  const moves = { ArrowLeft: [-10, 0], ArrowRight: [10, 0], ArrowUp: [0, 10], ArrowDown: [0, -10] };
  if (moves[event.key]) view.rotate(...moves[event.key]);
  else if (event.key === '+' || event.key === '=') view.zoom(1.2);
  else if (event.key === '-') view.zoom(1 / 1.2);
  else if (event.key === '0') view.resetCamera();
  else return;
  event.preventDefault();
  event.stopPropagation();
}

function summary(page) {
  const asked = page.lesson.steps.filter((step) => step.question);
  if (!asked.length) return null;
  const right = asked.filter((step) => page.progress.answers[String(step.index)]?.firstTry).length;
  return el('p', { class: 'summary', text: t('web.summary', { correct: right, total: asked.length }) });
}
