// A printed diagram as one SVG file: the drawn networks (SVG and the FBD canvases' HTML alike) inside a
// foreignObject, with the page's style rules, so the file shows exactly what the page shows.

/** The style rules of the page as one text (rules of other origins that cannot be read are left out). */
export function pageStyles(doc: Document): string {
  const rules: string[] = [];
  for (const sheet of Array.from(doc.styleSheets)) {
    try {
      for (const rule of Array.from(sheet.cssRules)) rules.push(rule.cssText);
    } catch {
      // a sheet of another origin: not ours, nothing of the diagram depends on it
    }
  }
  return rules.join("\n");
}

const escapeCss = (css: string) => css.replace(/]]>/g, "]] >");

/** `element` (a printed diagram) as an SVG document of its drawn size. */
export function diagramSvg(element: HTMLElement, styles: string): string {
  const box = element.getBoundingClientRect();
  const width = Math.ceil(box.width);
  const height = Math.ceil(box.height);
  const html = new XMLSerializer().serializeToString(element);
  return (
    `<svg xmlns="http://www.w3.org/2000/svg" width="${width}" height="${height}" viewBox="0 0 ${width} ${height}">` +
    `<style><![CDATA[${escapeCss(styles)}]]></style>` +
    `<foreignObject x="0" y="0" width="${width}" height="${height}">` +
    `<div xmlns="http://www.w3.org/1999/xhtml">${html}</div></foreignObject></svg>`
  );
}
