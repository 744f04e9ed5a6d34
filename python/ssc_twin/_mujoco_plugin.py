"""Entry point (group ``mujoco.plugins``): the mujoco package calls load() at import.

Importing the module loads libssc_plugin.so (a dependency of _core), whose constructor registers
the ``ssc.chamber_pressure`` sensor plugin with the running libmujoco; it also installs MuJoCo
message handlers that print instead of writing MUJOCO_LOG.TXT (where mujoco has none).
"""


def load():
    from . import _core

    _core.install_message_handlers()
