/** Which face the page shows: `?mode=present` (classroom), `?mode=embed` (iframes), else the editor. */
export type AppMode = 'editor' | 'present' | 'embed';

export function appMode(search: string): AppMode {
  const mode = new URLSearchParams(search).get('mode');
  return mode === 'present' || mode === 'embed' ? mode : 'editor';
}
