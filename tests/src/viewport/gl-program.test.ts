/** Driver info logs → diagnostics that name the node whose block holds the bad line. */
import { describe, expect, it } from 'vitest';
import { parseInfoLog } from '../../../src/viewport/gl-program.ts';

const lineMap = { 1: 'circleA', 2: 'mirrorB' };

describe('parseInfoLog', () => {
  it('maps the source-string number of each error to its node', () => {
    const log = [
      "ERROR: 2:3: 'kf_injected_error' : undeclared identifier",
      "ERROR: 0:41: 'runIis' : no matching overloaded function found",
      'ERROR: 2 compilation errors.  No code generated.',
      '',
    ].join('\n');
    const ds = parseInfoLog(log, lineMap, 'fragment');
    expect(ds).toHaveLength(3);
    expect(ds[0]).toMatchObject({ code: 'KF403', severity: 'error', nodeId: 'mirrorB' });
    expect(ds[0].message).toContain('node "mirrorB", line 3: \'kf_injected_error\' : undeclared identifier');
    // Source string 0 is the template: no node, the real line number.
    expect(ds[1].nodeId).toBeUndefined();
    expect(ds[1].message).toContain('fragment shader line 41');
    // A line in no known format is kept, so nothing the driver said is lost.
    expect(ds[2].message).toContain('2 compilation errors');
  });

  it('drops warnings and NUL padding, and never maps vertex errors to nodes', () => {
    expect(parseInfoLog('WARNING: 0:1: extension not supported\n\0', lineMap, 'fragment')).toEqual([]);
    const [d] = parseInfoLog("ERROR: 1:2: 'x' : syntax error", lineMap, 'vertex');
    expect(d.nodeId).toBeUndefined();
    expect(d.message).toContain('vertex shader line 2');
  });
});
