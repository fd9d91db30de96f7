/** A boolean UI preference kept in localStorage (panel open or closed); never part of the document. */
import { useCallback, useState } from 'react';

export function useRememberedFlag(key: string, fallback: boolean): [boolean, (v: boolean) => void] {
  const [value, setValue] = useState(() => {
    try {
      const v = localStorage.getItem(key);
      return v === null ? fallback : v === '1';
    } catch {
      return fallback;
    }
  });
  const set = useCallback(
    (v: boolean) => {
      setValue(v);
      try {
        localStorage.setItem(key, v ? '1' : '0');
      } catch {
        // a preference that is not remembered is not worth an error
      }
    },
    [key],
  );
  return [value, set];
}
