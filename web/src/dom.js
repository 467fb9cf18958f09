// Small helpers that build the page. Text goes in through textContent only: lesson files
// may come from strangers, and nothing in them is ever parsed as HTML.

/// Creates an element with attributes, text and children: el('p', {class: 'x'}, 'text').
export function el(tag, attributes = {}, ...children) {
  const node = document.createElement(tag);
  for (const [name, value] of Object.entries(attributes)) {
    if (value === false || value === null || value === undefined) continue;
    if (name.startsWith('on')) node.addEventListener(name.slice(2), value);
    else if (name === 'text') node.textContent = value;
    else node.setAttribute(name, value === true ? '' : String(value));
  }
  for (const child of children) {
    if (child === null || child === undefined || child === false) continue;
    node.append(typeof child === 'string' ? document.createTextNode(child) : child);
  }
  return node;
}

/// Paragraphs of a text whose paragraphs are separated by blank lines.
export function paragraphs(text, className) {
  const box = el('div', { class: className });
  for (const part of text.split(/\n\s*\n/)) {
    if (part.trim()) box.append(el('p', { text: part.trim() }));
  }
  return box;
}
