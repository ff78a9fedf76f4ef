/** The player's colour theme: follow the system, or always light or dark. */
export type ThemeChoice = 'system' | 'light' | 'dark';

const STORAGE_KEY = 'rtq.theme';

/** The remembered choice; 'system' when there is none or storage is blocked (reading `localStorage` itself can throw). */
export function savedTheme(): ThemeChoice {
  let saved: string | null | undefined;
  try {
    saved = globalThis.localStorage?.getItem(STORAGE_KEY);
  } catch {
    saved = null;
  }
  return saved === 'light' || saved === 'dark' ? saved : 'system';
}

/** Applies the choice to the page (theme.css reads [data-theme]) and remembers it. */
export function applyTheme(choice: ThemeChoice): void {
  const root = document.documentElement;
  if (choice === 'system') root.removeAttribute('data-theme');
  else root.setAttribute('data-theme', choice);
  try {
    if (choice === 'system') localStorage.removeItem(STORAGE_KEY);
    else localStorage.setItem(STORAGE_KEY, choice);
  } catch {
    // Storage can be blocked (private mode, school policy): the theme still applies now.
  }
}
