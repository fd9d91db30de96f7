/**
 * Whether this browser has seen the welcome card. Remembered in localStorage; where storage is
 * unavailable (private mode, blocked) the card shows once per page load and never throws.
 */
export const WELCOME_KEY = 'kleinflow.welcome.dismissed';

export function welcomeSeen(storage: Pick<Storage, 'getItem'> | undefined): boolean {
  try {
    return storage?.getItem(WELCOME_KEY) === '1';
  } catch {
    return false;
  }
}

export function rememberWelcome(storage: Pick<Storage, 'setItem'> | undefined): void {
  try {
    storage?.setItem(WELCOME_KEY, '1');
  } catch {
    // storage full or blocked: the card simply shows again next time
  }
}
