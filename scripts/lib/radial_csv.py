"""The CSV profile `nspd radial` prints (r,rho,u,p after '#' comment lines
and a header): the cell centres and densities."""


def read_profile(path):
    """(r, rho) lists of the profile in `path`"""
    r, rho = [], []
    for line in open(path):
        if line[0].isdigit():
            v = line.split(',')
            r.append(float(v[0]))
            rho.append(float(v[1]))
    return r, rho
