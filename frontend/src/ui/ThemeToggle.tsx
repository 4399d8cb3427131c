// The header's switch between the light and the dark theme.
import { Moon, Sun } from "lucide-react";
import { useState } from "react";
import { applyTheme, type Theme } from "./theme";
import { ToolButton } from "./ToolButton";

export function ThemeToggle() {
  const [theme, setTheme] = useState<Theme>(() =>
    document.documentElement.dataset.theme === "dark" ? "dark" : "light",
  );
  const dark = theme === "dark";
  return (
    <ToolButton
      icon={dark ? Sun : Moon}
      label="Dark theme"
      aria-pressed={dark}
      onClick={() => {
        const next: Theme = dark ? "light" : "dark";
        applyTheme(next);
        setTheme(next);
      }}
    />
  );
}
