// The print page as a static HTML file: what is drawn, with the page's style rules inlined and without
// the scripts and screen tools, so it opens anywhere and archives as it is.
import { pageStyles } from "./svg";

export function staticHtml(doc: Document): string {
  const copy = doc.documentElement.cloneNode(true) as HTMLElement;
  copy
    .querySelectorAll("script, link[rel=stylesheet], style, .print-toolbar, .print-screen-only")
    .forEach((e) => e.remove());
  const style = doc.createElement("style");
  style.textContent = pageStyles(doc);
  copy.querySelector("head")?.appendChild(style);
  return `<!doctype html>\n${copy.outerHTML}`;
}
