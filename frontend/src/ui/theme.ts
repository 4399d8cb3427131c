// The light and dark themes (issue 22 item 7): the choice is kept per browser; without one the system's
// preference decides. The theme is the `data-theme` attribute of <html>, which the style sheets' colour
// variables follow (styles.css).
export type Theme = "light" | "dark";

const KEY = "ladderlab:theme";

/** The theme chosen in this browser, else the system's preference. */
export function initialTheme(storage: Storage = localStorage, media = window.matchMedia?.bind(window)): Theme {
  const chosen = storage.getItem(KEY);
  if (chosen === "light" || chosen === "dark") return chosen;
  return media?.("(prefers-color-scheme: dark)").matches ? "dark" : "light";
}

/** Shows `theme` and keeps the choice. */
export function applyTheme(theme: Theme, storage: Storage = localStorage, root = document.documentElement): void {
  root.dataset.theme = theme;
  storage.setItem(KEY, theme);
}

/** Shows the kept theme without storing a choice (at start, before the app draws). */
export function showInitialTheme(root = document.documentElement): void {
  root.dataset.theme = initialTheme();
}
