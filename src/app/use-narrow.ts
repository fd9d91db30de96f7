/** Whether the window is phone-narrow: below this the app shows one pane at a time and a ☰ menu. */
import { useEffect, useState } from 'react';

/** Phones (390 px) and small tablets in portrait fall below; a 768 px tablet keeps both panes. */
export const NARROW_QUERY = '(max-width: 700px)';

export function useMediaQuery(query: string): boolean {
  const [matches, setMatches] = useState(() => window.matchMedia(query).matches);
  useEffect(() => {
    const list = window.matchMedia(query);
    const change = () => setMatches(list.matches);
    change();
    list.addEventListener('change', change);
    return () => list.removeEventListener('change', change);
  }, [query]);
  return matches;
}

export const useNarrow = () => useMediaQuery(NARROW_QUERY);
