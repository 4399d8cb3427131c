// The shortcut help: the keymap table (and the mouse gestures) of the scopes asked for, so what it
// lists is exactly what the key handlers do.
import { GESTURES, KEYMAP, SCOPE_TITLES, type KeyScope } from "./keymap";

export function ShortcutHelp({ scopes, onClose }: { scopes: readonly KeyScope[]; onClose(): void }) {
  return (
    <div className="ld-help" role="dialog" aria-label="Keyboard shortcuts">
      {scopes.map((scope) => (
        <section key={scope} aria-label={SCOPE_TITLES[scope]}>
          <h3>{SCOPE_TITLES[scope]}</h3>
          <table>
            <tbody>
              {KEYMAP.filter((b) => b.scope === scope).map((b) => (
                <tr key={b.command}>
                  <td>
                    <kbd>{b.keys}</kbd>
                  </td>
                  <td>{b.label}</td>
                </tr>
              ))}
              {GESTURES.filter((g) => g.scope === scope).map((g) => (
                <tr key={g.gesture}>
                  <td>
                    <kbd>{g.gesture}</kbd>
                  </td>
                  <td>{g.label}</td>
                </tr>
              ))}
            </tbody>
          </table>
        </section>
      ))}
      <button type="button" onClick={onClose}>
        Close
      </button>
    </div>
  );
}
