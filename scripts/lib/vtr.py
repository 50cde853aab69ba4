"""The .vtr files nspd writes (src/io/vtk.h: raw appended Float64 arrays,
each behind a UInt64 byte count), read without numpy: the cell array
`name` (x fastest) and the face coordinates along x and y."""
import re, struct


def _array(data, base, head, section, name):
    part = head[head.index('<' + section):]
    off = int(re.search(r'Name="%s"[^>]*offset="(\d+)"' % name, part).group(1))
    n = struct.unpack_from('<Q', data, base + off)[0] // 8
    return list(struct.unpack_from('<%dd' % n, data, base + off + 8))


def read_vtr(path, name='density'):
    """(x faces, y faces, cell values of `name`)"""
    data = open(path, 'rb').read()
    head = data[:data.index(b'<AppendedData')].decode()
    base = data.index(b'_', data.index(b'<AppendedData')) + 1
    return (_array(data, base, head, 'Coordinates', 'x'), _array(data, base, head, 'Coordinates', 'y'),
            _array(data, base, head, 'CellData', name))


def last_frame(outdir):
    """(time, path) of the last frame of OUTDIR/flow.pvd"""
    pvd = open(outdir + '/flow.pvd').read()
    t, f = re.findall(r'timestep="([^"]+)"[^>]*file="([^"]+)"', pvd)[-1]
    return float(t), outdir + '/' + f
