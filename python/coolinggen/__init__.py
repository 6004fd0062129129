"""CoolingGen from Python: builds, reports and the NURBS kernel (units mm, degrees).

    import coolinggen
    config = coolinggen.example()              # the built-in example as a dict
    result = coolinggen.build(config, outputs="none")
    result.valid, result.report["solid"]["volume_mm3"]
    result.write("out/blade")                  # the files of `coolinggen build -o out/blade`

Errors raise coolinggen.Error subclasses carrying the CLI's one-line messages: ConfigError (with
.field), FeatureFailure, Cancelled (timeout, Ctrl-C), OutputError, GeometryError (kernel input).
"""
from ._coolinggen import (  # noqa: F401
    __version__,
    Error,
    ConfigError,
    FeatureFailure,
    Cancelled,
    OutputError,
    GeometryError,
    Result,
    build,
    validate,
    example,
    BSplineCurve,
    BSplineSurface,
)

__all__ = [
    "__version__", "Error", "ConfigError", "FeatureFailure", "Cancelled", "OutputError", "GeometryError",
    "Result", "build", "validate", "example", "BSplineCurve", "BSplineSurface",
]
