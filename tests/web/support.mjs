// Helpers of the browser test: reading a site's data files, and comparing two PNG
// screenshots inside the browser (no PNG library needed): the fraction of pixels whose
// largest channel difference exceeds 24 of 255.
import { readFileSync } from 'node:fs';

/// The object a data file (RayLabSite.course({...}) / .lesson({...})) passes to the page.
export function decodeSiteData(file, call) {
  let value = null;
  const RayLabSite = { [call]: (data) => { value = data; } };
  new Function('RayLabSite', readFileSync(file, 'utf8'))(RayLabSite);
  return value;
}

export async function compareScreenshot(browser, pngA, pngB) {
  const page = await browser.newPage();
  try {
    return await page.evaluate(async (a, b) => {
      const load = async (base64) => {
        const image = new Image();
        image.src = `data:image/png;base64,${base64}`;
        await image.decode();
        const canvas = document.createElement('canvas');
        canvas.width = image.width;
        canvas.height = image.height;
        const context = canvas.getContext('2d');
        context.drawImage(image, 0, 0);
        return context.getImageData(0, 0, image.width, image.height);
      };
      const [first, second] = [await load(a), await load(b)];
      if (first.width !== second.width || first.height !== second.height) return { sameSize: false, changed: 1 };
      let changed = 0;
      for (let i = 0; i < first.data.length; i += 4) {
        const d = Math.max(Math.abs(first.data[i] - second.data[i]), Math.abs(first.data[i + 1] - second.data[i + 1]),
          Math.abs(first.data[i + 2] - second.data[i + 2]));
        if (d > 24) changed += 1;
      }
      return { sameSize: true, changed: changed / (first.width * first.height) };
    }, Buffer.from(pngA).toString('base64'), Buffer.from(pngB).toString('base64'));
  } finally {
    await page.close();
  }
}
