// The browser test of the web export (issue 34): opens an exported lesson from file:// in
// Debian's Chromium (headless, through puppeteer-core; no browser is ever downloaded) with
// every non-file request refused, and checks what a student does: no console errors, no
// network request, every step shown, the 3D view turns (its pixels change), a question
// answered wrong then right, the page switched to Chinese, the progress kept and reset,
// and screenshots of chosen steps close to baselines in tests/baselines/web/.
//
//   node TestWebLesson.mjs --lesson ID --baselines DIR --out DIR [--prefix NAME] [--chromium PATH]
//       [--modules DIR]   (baselines: DIR/NAME_step_en.png, ...; NAME TestWebLesson by default)
//       either --raylab EXE --lesson-file FILE [--with-display SCRIPT]  (`raylab web`'s site)
//       or     --fixture DIR --bundle DIR        (a hand-made site + the built bundle)
// Exit 0: passed, 1: failed, 77: skipped (no Chromium or no web/node_modules).
import { spawnSync } from 'node:child_process';
import { cpSync, existsSync, mkdirSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { join, resolve } from 'node:path';
import { pathToFileURL } from 'node:url';
import { compareScreenshot, decodeSiteData } from './support.mjs';

const args = Object.fromEntries(process.argv.slice(2).reduce((pairs, word, i, all) =>
  (word.startsWith('--') ? [...pairs, [word.slice(2), all[i + 1]]] : pairs), []));
const chromium = args.chromium || '/usr/bin/chromium';
args.prefix ??= 'TestWebLesson';
const failures = [];
const check = (ok, what) => { if (!ok) failures.push(what); console.log(`${ok ? 'ok  ' : 'FAIL'} ${what}`); };

let puppeteer;
try {
  puppeteer = createRequire(resolve(args.modules || 'web/node_modules') + '/')('puppeteer-core');
} catch (error) {
  console.log(`SKIP: puppeteer-core not installed (run npm ci --prefix web): ${error.message}`);
  process.exit(77);
}
if (!existsSync(chromium)) {
  console.log(`SKIP: no Chromium at ${chromium} (apt-get install chromium)`);
  process.exit(77);
}

mkdirSync(args.out, { recursive: true });
const site = resolve(args.out, 'site');
rmSync(site, { recursive: true, force: true });
if (args.raylab) {
  // raylab draws each step's view with VTK, which needs an X display (with-display.sh).
  const command = [args.raylab, 'web', '--out', site, args['lesson-file']];
  if (args['with-display']) command.unshift(args['with-display']);
  const started = performance.now();
  const run = spawnSync(command[0], command.slice(1), { encoding: 'utf8' });
  console.log(`measure: raylab web of ${args['lesson-file']} took ${((performance.now() - started) / 1000).toFixed(1)} s`);
  if (run.status !== 0) {
    console.log(`FAIL raylab web --out ${site} ${args['lesson-file']}: exit ${run.status}\n${run.stdout}${run.stderr}`);
    process.exit(1);
  }
} else {
  cpSync(args.fixture, site, { recursive: true });
  for (const name of ['raylab-web.js', 'raylab-web.css']) cpSync(join(args.bundle, name), join(site, name));
}
const course = decodeSiteData(join(site, 'course.js'), 'course');
const lesson = decodeSiteData(join(site, 'lessons', `${args.lesson}.js`), 'lesson');
const phrase = (key, lang, values = {}) =>
  course.phrases[key][lang].replace(/\{(\w+)\}/g, (w, name) => String(values[name] ?? w));

const browser = await puppeteer.launch({
  executablePath: chromium, headless: true,
  args: ['--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--lang=en-US',
    '--font-render-hinting=none', '--force-color-profile=srgb', '--hide-scrollbars'],
});
const errors = [];
const requests = [];
try {
  const page = await browser.newPage();
  await page.setViewport({ width: 1200, height: 900, deviceScaleFactor: 1 });
  await page.setRequestInterception(true);
  page.on('request', (request) => {
    const url = request.url();
    if (url.startsWith('file://') || url.startsWith('data:')) request.continue();
    else { requests.push(url); request.abort(); }
  });
  page.on('console', (message) => { if (message.type() === 'error') errors.push(message.text()); });
  page.on('pageerror', (error) => errors.push(String(error)));
  page.on('requestfailed', (request) => {
    if (request.url().startsWith('file://')) errors.push(`missing file ${request.url()}`);
  });
  page.on('dialog', (dialog) => dialog.accept());
  const text = (selector) => page.$eval(selector, (node) => node.textContent);

  // The index lists the lesson; its link opens the lesson page.
  await page.goto(pathToFileURL(join(site, 'index.html')).href);
  check(await text('h1') === phrase('web.course_title', 'en'), 'index: course title in English');
  const link = await page.$(`a[href="lessons/${args.lesson}.html"]`);
  check(Boolean(link), 'index: a link to the lesson');
  await Promise.all([page.waitForNavigation(), link.click()]);
  await page.waitForSelector('#step-title');
  // Time to the first interactive 3D step: the lesson opened (reloaded) at its first 3D step.
  const firstViewStep = lesson.steps.find((step) => step.view3d);
  await page.evaluate((id, index) => localStorage.setItem(`raylab.lesson.${id}`,
    JSON.stringify({ step: index, seen: [], answers: {} })), lesson.id, firstViewStep.index);
  await page.reload();
  await page.waitForSelector('.view canvas');
  const times = await page.evaluate(() => window.raylabTimings);
  await page.evaluate((id) => localStorage.removeItem(`raylab.lesson.${id}`), lesson.id);
  await page.reload();
  await page.waitForSelector('#step-title');
  console.log(`measure: ms after navigation start: bundle running ${times.bundleStart.toFixed(0)}, ` +
    `data read and page started ${times.start.toFixed(0)}, first 3D view drawn ${times.firstView?.toFixed(0)}`);
  check(times.firstView !== undefined, 'the first step\'s 3D view was drawn');

  // Every step, forwards with the → key; the step title and "Step n of N" follow.
  for (const step of lesson.steps) {
    check(await text('#step-title') === step.title.en, `step ${step.index + 1}: title "${step.title.en}"`);
    check(await text('.step-of') === phrase('web.step_of', 'en', { n: step.index + 1, total: lesson.steps.length }),
      `step ${step.index + 1}: "Step n of N"`);
    const hasView = Boolean(await page.$('.view canvas'));
    check(hasView === Boolean(step.view3d), `step ${step.index + 1}: 3D view ${step.view3d ? 'shown' : 'absent'}`);
    await page.keyboard.press('ArrowRight');
  }
  check(await text('#step-title') === lesson.steps.at(-1).title.en, 'the → key stops at the last step');
  await page.keyboard.press('ArrowLeft');
  check(await text('#step-title') === lesson.steps.at(-2).title.en, 'the ← key goes back');

  // The 3D view turns under the mouse: its pixels change.
  const shown = lesson.steps.filter((step) => step.view3d && !step.view3d.hidden && step.view3d.rays.length);
  const viewStep = shown.find((step) => step.layout === 'scene') ?? shown[0];
  await page.click(`nav.steps li:nth-child(${viewStep.index + 1}) button`);
  const canvas = await page.waitForSelector('.view canvas');
  const box = await canvas.boundingBox();
  await page.evaluate(() => document.activeElement?.blur());
  const before = await canvas.screenshot();
  writeFileSync(join(args.out, 'view_before_drag.png'), before);
  await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
  await page.mouse.down();
  await page.mouse.move(box.x + box.width / 2 + 150, box.y + box.height / 2 + 40, { steps: 10 });
  await page.mouse.up();
  const after = await canvas.screenshot();
  writeFileSync(join(args.out, 'view_after_drag.png'), after);
  const turned = await compareScreenshot(browser, before, after);
  console.log(`measure: ${(100 * turned.changed).toFixed(1)}% of the view's pixels changed by the drag`);
  check(turned.changed > 0.02, 'dragging turns the 3D view (over 2% of its pixels change)');
  await page.click('.reset-view');
  const reset = await compareScreenshot(browser, before, await canvas.screenshot());
  check(reset.changed < 0.001, '"Reset view" brings the camera back');

  // By keyboard: the view takes focus and turns with the arrow keys; the depth slider takes
  // the tree back to depth 0 and the narration of that depth is read out (aria-live).
  await page.focus('.view');
  await page.keyboard.press('ArrowLeft');
  const keyed = await compareScreenshot(browser, before, await canvas.screenshot());
  check(keyed.changed > 0.02, 'the ← key turns the focused 3D view');
  check(await text('#step-title') === viewStep.title.en, 'the ← key in the 3D view does not change the step');
  await page.click('.reset-view');
  await page.focus('#depth');
  await page.keyboard.press('Home');
  const spoken = viewStep.narration.filter((line) => line.depth === 0).map((line) => line.text.en).join(' ');
  check(await text('.narration-live') === spoken, 'depth slider at 0: the narration of depth 0 is read out');
  const shallower = await compareScreenshot(browser, before, await canvas.screenshot());
  check(shallower.changed > 0.002, `depth slider at 0: only the camera ray is left (${(100 * shallower.changed).toFixed(2)}% of pixels change)`);

  await answerQuestions(page, text, check, phrase, lesson);
  await checkVerdicts(page, text, check, phrase, lesson);
  const stepEn = lesson.steps.find((step) => step.view3d && step.question);
  await screenshot(page, `${args.prefix}_step_en`, stepEn, null);

  // A 3D step other than the first, shown from its view down (legend, depth, narration),
  // in English (the README's picture) and, below, in Chinese.
  const zhSteps = lesson.steps.filter((step) => step.view3d && !step.view3d.hidden && step.narration.length &&
    step !== stepEn);
  const zhStep = zhSteps.find((step) => step.layout === 'scene') ?? zhSteps[0] ?? lesson.steps[0];
  await screenshot(page, `${args.prefix}_view_en`, zhStep, '.tree-box');

  // Chinese: the page's words and the lesson's text switch.
  await page.click('[data-lang="zh"]');
  await page.click(`nav.steps li:nth-child(${zhStep.index + 1}) button`);
  check(await text('#step-title') === zhStep.title.zh, 'Chinese: the step title is the Chinese one');
  check(await text('.step-of') === phrase('web.step_of', 'zh', { n: zhStep.index + 1, total: lesson.steps.length }),
    'Chinese: "第 n 步" from the phrases');
  check(await page.evaluate(() => document.documentElement.lang) === 'zh-CN', 'Chinese: <html lang="zh-CN">');
  await screenshot(page, `${args.prefix}_view_zh`, zhStep, '.tree-box');
  await page.reload();
  await page.waitForSelector('#step-title');
  check(await text('#step-title') === zhStep.title.zh, 'after a reload: the same step, still in Chinese');

  // Back on the index: progress in Chinese, then "reset" forgets it.
  await Promise.all([page.waitForNavigation(), page.click('a.back')]);
  const total = lesson.steps.length;
  check(await text('.progress-text') === phrase('web.progress', 'zh', { done: total, total }), 'index: every step counted as seen');
  await screenshot(page, `${args.prefix}_index_zh`, null, null);
  await page.click('button.reset');
  check(await text('.progress-text') === phrase('web.progress', 'zh', { done: 0, total }), 'index: reset forgets the progress');
  const leftover = await page.evaluate(() => document.body.innerText.match(/\bweb\.[a-z_]+/g));
  check(!leftover, `no phrase key shown instead of words (${leftover})`);
} catch (error) {
  check(false, `the test ran to its end (${error.message})`);
} finally {
  await browser.close();
}
check(errors.length === 0, `no console errors${errors.length ? `: ${errors.join(' | ')}` : ''}`);
check(requests.length === 0, `no network requests${requests.length ? `: ${requests.join(' ')}` : ''}`);
if (failures.length) {
  console.log(`${failures.length} checks failed`);
  process.exit(1);
}
console.log('all checks passed');

/// Takes the page's screenshot (of a step, scrolled to an element) and compares it with
/// tests/baselines/web/NAME.png.
async function screenshot(page, name, step, scrollTo) {
  if (step) await page.click(`nav.steps li:nth-child(${step.index + 1}) button`);
  await page.evaluate((selector) => {
    document.activeElement?.blur();
    window.scrollTo(0, selector ? document.querySelector(selector).getBoundingClientRect().top + window.scrollY - 8 : 0);
  }, scrollTo);
  const shot = await page.screenshot({ fullPage: false });
  writeFileSync(join(args.out, `${name}.png`), shot);
  const baseline = join(args.baselines, `${name}.png`);
  if (!existsSync(baseline)) {
    check(false, `${name}: no baseline; look at ${join(args.out, `${name}.png`)} and copy it to ${baseline}`);
    return;
  }
  const diff = await compareScreenshot(browser, readFileSync(baseline), shot);
  console.log(`measure: ${name} differs from its baseline in ${(100 * diff.changed).toFixed(2)}% of pixels`);
  check(diff.sameSize && diff.changed < 0.01, `${name}: matches its baseline (under 1% of pixels off by more than 24/255)`);
}

/// The first number question wrong then right; a predict step's tree waits for the answer.
async function answerQuestions(page, text, check, phrase, lesson) {
  const numberStep = lesson.steps.find((step) => step.question?.type === 'number');
  if (numberStep && numberStep.question.answer !== null) {
    await page.click(`nav.steps li:nth-child(${numberStep.index + 1}) button`);
    const q = numberStep.question;
    await page.type('.question input', String(q.answer + 10 * (q.tolerance || 1) + 1));
    await page.keyboard.press('Enter');
    check((await text('.feedback')).includes(phrase('web.try_again', 'en')), 'a wrong answer: "try again"');
    if (q.hint) check((await text('.feedback')).includes(q.hint.en), 'a wrong answer: the hint');
    await page.$eval('.question input', (input) => { input.value = ''; });
    await page.type('.question input', String(q.answer));
    await page.keyboard.press('Enter');
    check((await text('.feedback')).includes(phrase('web.correct', 'en')), 'the right answer: "correct"');
  }
  const predicts = lesson.steps.filter((step) => step.view3d?.hidden && step.question && step !== numberStep);
  const predict = predicts.find((step) => step.question.type === 'choice') ?? predicts[0];
  if (predict && predict.question.answer !== null) {
    await page.click(`nav.steps li:nth-child(${predict.index + 1}) button`);
    check(!(await page.$('#depth')), 'predict step: the tree waits for an answer');
    const q = predict.question;
    if (q.type === 'choice') await page.click(`.question input[value="${(q.answer + 1) % q.choices.length}"]`);
    else await page.type('.question input', String(q.answer + 10 * (q.tolerance || 1) + 1));
    await page.click('.question .check');
    check(Boolean(await page.$('#depth')), 'predict step: the tree is shown once an answer is committed');
    await page.click('.question .reveal');
    const answer = q.type === 'choice' ? q.choices[q.answer].en : String(q.answer);
    check((await text('.feedback')).includes(phrase('web.answer_is', 'en', { answer })),
      'predict step: "Show the answer" reveals it');
  }
}

/// A bug-hunt step (view3d.verdicts): before an answer only a note, no verdicts (they would
/// point at the bug); once answered, "colour by verdict" redraws the tree by verdict beside
/// the correct engine's, with the verdicts named in the legend.
async function checkVerdicts(page, text, check, phrase, lesson) {
  const hunt = lesson.steps.find((step) => step.view3d?.verdicts && step.question);
  if (!hunt || hunt.question.answer === null) return;  // the fixture has none
  await page.click(`nav.steps li:nth-child(${hunt.index + 1}) button`);
  check(!(await page.$('#verdicts')) && await text('.verdict-later') === phrase('web.verdict_later', 'en'),
    'bug hunt: before an answer, a note and no verdict colouring');
  const q = hunt.question;
  if (q.type === 'choice') await page.click(`.question input[value="${q.answer}"]`);
  else await page.type('.question input', String(q.answer));
  await page.click('.question .check');
  await page.waitForSelector('#verdicts');
  await page.evaluate(() => document.activeElement?.blur());
  const before = await (await page.$('.view canvas')).screenshot();
  await page.click('#verdicts');
  await page.waitForSelector('.verdict-note');
  await page.evaluate(() => document.activeElement?.blur());
  const legend = await text('.legend');
  check(legend.includes('wrong weight') && legend.includes(phrase('web.verdict_reference', 'en')),
    `bug hunt: the verdict legend in words (${legend})`);
  const after = await (await page.$('.view canvas')).screenshot();
  const redrawn = await compareScreenshot(page.browser(), before, after);
  console.log(`measure: colour by verdict changes ${(100 * redrawn.changed).toFixed(2)}% of the view's pixels`);
  check(redrawn.changed > 0.001, 'bug hunt: the tree is redrawn by verdict');
  await page.evaluate(() => window.scrollTo(0, document.querySelector('.tree-box').getBoundingClientRect().top + window.scrollY - 8));
  writeFileSync(join(args.out, `${args.prefix}_verdicts_en.png`), await page.screenshot({ fullPage: false }));
}
