"""Every range domain of the plugin's proxies is Core's range of that option
(sltk/recon/OptionRanges.h, the one table the filters, the CLI and the XML
take their ranges from): the same minimum and maximum on every component, a
domain from 0 where 0 means automatic; and every row of Core's table is some
proxy's property. The table comes from the wrapped filter
(vtkSLLevelSetReconstruct.GetPropertyRange*), the domains from the loaded XML."""
import sys

from paraview import servermanager
from paraview.simple import LoadPlugin

import sltk

LoadPlugin(sys.argv[1], ns=globals())
table = sltk.vtkSLLevelSetReconstruct
core = {}
for i in range(table.GetNumberOfPropertyRanges()):
    core[table.GetPropertyRangeName(i)] = (table.GetPropertyRangeMinimum(i), table.GetPropertyRangeMaximum(i),
                                           table.GetPropertyRangeZeroIsAutomatic(i))
assert len(core) >= 19, "Core's table has %d rows" % len(core)

checked = set()
for group, name in (("sources", "CWENOHJBSolver"), ("filters", "SLLevelSetReconstruct"), ("filters", "OctreeSDF")):
    proxy = servermanager.ProxyManager().NewProxy(group, name)
    assert proxy is not None, "the plugin has no %s proxy" % name
    it = proxy.NewPropertyIterator()
    it.Begin()
    while not it.IsAtEnd():
        prop = it.GetProperty()
        key = it.GetKey()
        domain = prop.GetDomain("range")
        if domain is not None:
            assert key in core, "%s.%s has a range domain but no row in Core's table" % (name, key)
            low, high, automatic = core[key]
            expected_low = 0.0 if automatic else low
            for k in range(prop.GetNumberOfElements()):
                got = (domain.GetMinimum(k), domain.GetMaximum(k))
                assert got == (expected_low, high), \
                    "%s.%s[%d]: the XML's range %s, Core's %s" % (name, key, k, got, (expected_low, high))
            checked.add(key)
        it.Next()
missing = set(core) - checked
assert not missing, "Core's table has rows no proxy's domain shows: %s" % sorted(missing)
print("%d ranges: every proxy domain is Core's" % len(checked))
