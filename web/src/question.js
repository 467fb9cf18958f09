// A step's question with self-check, by the window's rules (issue 33.6): the first wrong try
// says "try again" (with the hint); the answer is revealed on request or after the second
// wrong try; a predict step's tree is shown once an answer is committed. In the student
// version (answer null) nothing is checked and the page says so.
import { el, paragraphs } from './dom.js';
import { pick, t } from './words.js';

/// Whether a typed number is right within the question's tolerance.
function numberIsRight(question, value) {
  const tolerance = question.tolerance ?? 1e-9 * Math.max(1, Math.abs(question.answer));
  return Math.abs(value - question.answer) <= tolerance;
}

/// The answer as the student reads it: the number, or the text of the right choice.
function answerText(question) {
  return question.type === 'choice' ? pick(question.choices[question.answer]) : String(question.answer);
}

function readValue(question, form) {
  if (question.type === 'choice') {
    const checked = form.querySelector('input[type=radio]:checked');
    return checked ? Number(checked.value) : null;
  }
  const text = form.querySelector('input').value.trim().replace(',', '.');
  return text === '' || Number.isNaN(Number(text)) ? null : Number(text);
}

function inputs(question, state, disabled) {
  if (question.type === 'choice') {
    return el('fieldset', {}, el('legend', { class: 'visually-hidden', text: pick(question.prompt) }),
      ...question.choices.map((choice, i) => el('label', { class: 'choice' },
        el('input', { type: 'radio', name: 'choice', value: i, checked: state.value === i, disabled }),
        ` ${pick(choice)}`)));
  }
  return el('input', { type: 'text', inputmode: 'decimal', autocomplete: 'off', 'aria-label': t('web.answer_placeholder'),
    placeholder: t('web.answer_placeholder'), value: state.value ?? '', disabled });
}

/// The feedback lines for the current state.
function feedback(question, state, problem) {
  const lines = [];
  const keyless = question.answer === null || question.answer === undefined;
  if (problem) lines.push(el('p', { class: 'wrong', text: problem }));
  if (keyless && state.tries > 0) lines.push(el('p', { class: 'note', text: t('web.no_key') }));
  if (keyless) return lines;
  if (state.correct) lines.push(el('p', { class: 'right', text: t('web.correct') }));
  else if (state.tries > 0 && !state.revealed) {
    lines.push(el('p', { class: 'wrong', text: t('web.try_again') }));
    if (question.hint) lines.push(el('p', { class: 'hint' }, el('strong', { text: `${t('web.hint')}: ` }), pick(question.hint)));
  }
  if (state.revealed && !state.correct) lines.push(el('p', { class: 'answer', text: t('web.answer_is', { answer: answerText(question) }) }));
  if ((state.correct || state.revealed) && question.explanation) {
    lines.push(el('p', { class: 'explanation' }, el('strong', { text: `${t('web.explanation')}: ` }), pick(question.explanation)));
  }
  return lines;
}

/// Renders the question into a section; `state` is the kept answer (mutated), `onChange`
/// is called after every commit so the page saves progress and shows a predict step's tree.
export function questionSection(question, state, onChange) {
  const section = el('section', { class: 'question', 'aria-labelledby': 'question-title' });
  const keyless = question.answer === null || question.answer === undefined;
  const done = state.correct || state.revealed || (keyless && state.tries > 0);
  const live = el('div', { class: 'feedback', role: 'status', 'aria-live': 'polite' });

  function commit(event) {
    event.preventDefault();
    const value = readValue(question, form);
    if (value === null) {
      live.replaceChildren(...feedback(question, state, t('web.not_a_number')));
      return;
    }
    state.value = value;
    state.tries += 1;
    if (!keyless) {
      const right = question.type === 'choice' ? value === question.answer : numberIsRight(question, value);
      if (right) state.correct = true;
      if (right && state.tries === 1) state.firstTry = true;
      if (!right && state.tries >= 2) state.revealed = true;
    }
    onChange();
  }

  const form = el('form', { onsubmit: commit },
    el('h3', { id: 'question-title', text: t('web.question') }),
    question.predict ? el('p', { class: 'predict', text: t('web.predict') }) : null,
    paragraphs(pick(question.prompt), 'prompt'),
    inputs(question, state, done),
    el('div', { class: 'buttons' },
      el('button', { type: 'submit', class: 'check', disabled: done, text: t('web.check') }),
      !keyless && state.tries > 0 && !done
        ? el('button', { type: 'button', class: 'reveal', text: t('web.show_answer'),
          onclick: () => { state.revealed = true; onChange(); } })
        : null));
  live.replaceChildren(...feedback(question, state, null));
  section.append(form, live);
  return section;
}
