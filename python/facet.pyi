# Type stubs of the `facet` module (python/facet_module.cpp), installed beside
# it; tests/python/stub_test.py holds every signature here to the module's.
from os import PathLike
from typing import Callable, Optional, Union

import numpy
import numpy.typing

Vec3 = tuple[float, float, float]
SceneOrPath = Union["Scene", str, PathLike[str]]

__version__: str

class Error(ValueError):
    exit_code: int

class Material:
    name: str
    preset: Optional[str]
    distribution: Optional[str]
    geometry: Optional[str]
    fresnel: Optional[str]
    alpha: Optional[float]
    roughness: Optional[float]
    f0: Optional[Vec3]
    ior: Optional[Vec3]
    eta: Optional[Vec3]
    k: Optional[Vec3]
    diffuse: Optional[Vec3]
    base_color: Optional[Vec3]
    metallic: Optional[float]
    energy_compensation: bool
    transmission: Optional[float]
    thin_walled: Optional[bool]
    attenuation_color: Optional[Vec3]
    attenuation_distance: Optional[float]
    thickness: Optional[float]
    anisotropy: Optional[float]
    anisotropy_rotation: Optional[float]
    clearcoat: Optional[float]
    clearcoat_roughness: Optional[float]
    sheen_color: Optional[Vec3]
    sheen_roughness: Optional[float]
    iridescence: Optional[float]
    iridescence_ior: Optional[float]
    iridescence_thickness: Optional[float]
    def __init__(self, *, name: str = "", preset: Optional[str] = None, distribution: Optional[str] = None,
                 geometry: Optional[str] = None, fresnel: Optional[str] = None, alpha: Optional[float] = None,
                 roughness: Optional[float] = None, f0: Optional[Vec3] = None, ior: Optional[Vec3] = None,
                 eta: Optional[Vec3] = None, k: Optional[Vec3] = None, diffuse: Optional[Vec3] = None,
                 base_color: Optional[Vec3] = None, metallic: Optional[float] = None,
                 energy_compensation: bool = False, transmission: Optional[float] = None,
                 thin_walled: Optional[bool] = None, attenuation_color: Optional[Vec3] = None,
                 attenuation_distance: Optional[float] = None, thickness: Optional[float] = None,
                 anisotropy: Optional[float] = None, anisotropy_rotation: Optional[float] = None,
                 clearcoat: Optional[float] = None, clearcoat_roughness: Optional[float] = None,
                 sheen_color: Optional[Vec3] = None, sheen_roughness: Optional[float] = None,
                 iridescence: Optional[float] = None, iridescence_ior: Optional[float] = None,
                 iridescence_thickness: Optional[float] = None) -> None: ...

class Cage:
    positions: numpy.ndarray  # read-only, (n, 3), its array not writeable
    face_vertex_counts: tuple[int, ...]  # read-only
    face_vertex_indices: tuple[int, ...]  # read-only
    creases: tuple[tuple[int, int, float], ...]  # read-only
    def __init__(self, positions: numpy.typing.ArrayLike, face_vertex_counts: numpy.typing.ArrayLike,
                 face_vertex_indices: numpy.typing.ArrayLike, creases: list[tuple[int, int, float]] = []) -> None: ...

def load_cage(path: Union[str, PathLike[str]]) -> Cage: ...

# Scaled, then rotated (degrees about x, then y, then z), then translated, as a scene file's objects[].transform.
class Transform:
    translate: Vec3
    rotate: Vec3
    scale: Vec3
    def __init__(self, *, translate: Vec3 = (0.0, 0.0, 0.0), rotate: Vec3 = (0.0, 0.0, 0.0),
                 scale: Vec3 = (1.0, 1.0, 1.0)) -> None: ...

class Object:
    def __init__(self, cage: Cage, *, material: int = 0, name: str = "", subdivided: bool = True,
                 transform: Optional[Transform] = None) -> None: ...  # None: where the cage is

# Light, Camera and Environment are values: their fields are read-only; replace() gives a changed copy.
class Light:
    type: str
    color: Vec3
    position: Vec3
    direction: Vec3
    inner_cone: float
    outer_cone: float
    def __init__(self, type: str = "directional", *, color: Vec3 = (1.0, 1.0, 1.0), position: Vec3 = (0.0, 0.0, 0.0),
                 direction: Vec3 = (0.0, -1.0, 0.0), inner_cone: float = 30.0, outer_cone: float = 45.0) -> None: ...
    def replace(self, *, type: Optional[str] = None, color: Optional[Vec3] = None, position: Optional[Vec3] = None,
                direction: Optional[Vec3] = None, inner_cone: Optional[float] = None,
                outer_cone: Optional[float] = None) -> Light: ...

class Camera:
    eye: Vec3
    target: Vec3
    up: Vec3
    fov: float
    def __init__(self, *, eye: Vec3 = (0.0, 0.0, 5.0), target: Vec3 = (0.0, 0.0, 0.0), up: Vec3 = (0.0, 1.0, 0.0),
                 fov: float = 40.0) -> None: ...
    def replace(self, *, eye: Optional[Vec3] = None, target: Optional[Vec3] = None, up: Optional[Vec3] = None,
                fov: Optional[float] = None) -> Camera: ...

class Environment:
    file: str
    intensity: float
    rotation: float
    method: Optional[str]  # sampled, prefiltered or filtered; None: chosen, sampled where paths run
    samples: Optional[int]  # pairs per camera sample; None: chosen, 16 unless paths run
    occlusion: bool
    def __init__(self, file: Union[str, PathLike[str]], *, intensity: float = 1.0, rotation: float = 0.0,
                 method: Optional[str] = None, samples: Optional[int] = None, occlusion: bool = True) -> None: ...
    def replace(self, *, file: Optional[Union[str, PathLike[str]]] = None, intensity: Optional[float] = None,
                rotation: Optional[float] = None, method: Optional[str] = None, samples: Optional[int] = None,
                occlusion: Optional[bool] = None) -> Environment: ...

class SceneObject:
    @property
    def name(self) -> str: ...
    # Its material's name; a Material, a preset name or a material file (.json) changes it.
    @property
    def material(self) -> str: ...
    @material.setter
    def material(self, value: Union[Material, str, PathLike[str]]) -> None: ...
    # The Transform that places its cage, as its scene file's transform; assigning one moves it.
    @property
    def transform(self) -> Transform: ...
    @transform.setter
    def transform(self, value: Transform) -> None: ...

class Scene:
    camera: Camera
    environment: Optional[Environment]
    def __init__(self, objects: list[Object], *, materials: list[Material] = [], lights: list[Light] = [],
                 camera: Optional[Camera] = None, environment: Optional[Environment] = None,
                 size: tuple[int, int] = (512, 512)) -> None: ...
    @property
    def size(self) -> tuple[int, int]: ...
    @property
    def object_count(self) -> int: ...
    @property
    def objects(self) -> tuple[SceneObject, ...]: ...
    @property
    def material_names(self) -> tuple[str, ...]: ...
    # A tuple, so that an append cannot seem to add a light; assign a list to change them.
    @property
    def lights(self) -> tuple[Light, ...]: ...
    @lights.setter
    def lights(self, value: list[Light]) -> None: ...
    # Returns the new object's index; material (a Material, a preset or a file) in place of its material index.
    def add_object(self, object: Object, *, material: Optional[Union[Material, str, PathLike[str]]] = None) -> int: ...
    def remove_object(self, index: int) -> None: ...
    def move_object(self, index: int, to: int) -> None: ...
    # What `facet render --set PATH=VALUE` does to a scene file; value is any JSON-able Python value.
    def set(self, path: str, value: object) -> None: ...
    @property
    def warnings(self) -> tuple[str, ...]: ...

def load_scene(path: Union[str, PathLike[str]], *, variant: str = "") -> Scene: ...
# A scene file's JSON as a dict; the files it names are relative to folder.
def load_dict(scene: dict, *, folder: Union[str, PathLike[str]] = ".") -> Scene: ...

class Renderer:
    def __init__(self, adapter: str = "") -> None: ...
    def render(self, scene: SceneOrPath, *, size: Optional[tuple[int, int]] = None, backend: str = "gpu",
               method: Optional[str] = None, spp: Optional[int] = None, tess_level: Optional[int] = None,
               bounces: Optional[int] = None, exr: Optional[str] = None, png: Optional[str] = None,
               aovs: str = "all", half: bool = False, exposure: float = 0.0, tonemap: str = "pbr-neutral",
               background: Optional[Vec3] = None, alpha: bool = False) -> dict: ...
    def parity(self, scene: SceneOrPath, *, size: Optional[tuple[int, int]] = None,
               method: Optional[str] = None, renders: int = 16, tolerances: list[str] = [],
               min_coverage: int = 16) -> dict: ...
    # facet render --watch: callback({"picture", "passes", "spp", "image"}) after each pass, False to stop;
    # variant: a glTF file's material variant, as --variant;
    # on_bad_input(message) for a later load refused, False to stop; without it such a load ends the watch.
    def watch(self, scene: Union[str, PathLike[str]], callback: Callable[[dict], Optional[bool]], *,
              passes: int = 16, changes: int = 0, size: Optional[tuple[int, int]] = None, backend: str = "gpu",
              method: Optional[str] = None, spp: Optional[int] = None, tess_level: Optional[int] = None,
              bounces: Optional[int] = None, variant: str = "",
              on_bad_input: Optional[Callable[[str], Optional[bool]]] = None) -> None: ...
    # The preview stage: {"frame", "pictures": [{"label", "rgba", "image", "adaptive"}], "sheet"}.
    def preview(self, model: SceneOrPath, materials: list[Union[str, PathLike[str]]], *, frame: int = 0,
                size: tuple[int, int] = (256, 256), columns: int = 0, ground: bool = True,
                environment: Optional[Environment] = None, noise_threshold: float = 0.02, max_spp: int = 256,
                time_limit: Optional[float] = None, turntable: Optional[int] = None, turn: str = "model",
                backend: str = "gpu", exposure: float = 0.0, tonemap: str = "pbr-neutral") -> dict: ...
    # What facet preview writes: the sheet (.png), or with a turntable the movie (.mp4, .gif) by ffmpeg.
    def write_preview(self, model: SceneOrPath, materials: list[Union[str, PathLike[str]]],
                      output: Union[str, PathLike[str]], *, fps: float = 24.0, size: tuple[int, int] = (256, 256),
                      columns: int = 0, ground: bool = True, environment: Optional[Environment] = None,
                      noise_threshold: float = 0.02, max_spp: int = 256, time_limit: Optional[float] = None,
                      turntable: Optional[int] = None, turn: str = "model", backend: str = "gpu",
                      exposure: float = 0.0, tonemap: str = "pbr-neutral") -> None: ...

def render(scene: SceneOrPath, *, size: Optional[tuple[int, int]] = None, backend: str = "gpu",
           method: Optional[str] = None, spp: Optional[int] = None, tess_level: Optional[int] = None,
           bounces: Optional[int] = None, adapter: str = "", exr: Optional[str] = None, png: Optional[str] = None,
           aovs: str = "all", half: bool = False, exposure: float = 0.0, tonemap: str = "pbr-neutral",
           background: Optional[Vec3] = None, alpha: bool = False) -> dict: ...

# facet parity's --json entry of the scene, with verdict, pass, renders and summary.
def parity(scene: SceneOrPath, *, size: Optional[tuple[int, int]] = None, method: Optional[str] = None,
           adapter: str = "", renders: int = 16, tolerances: list[str] = [], min_coverage: int = 16) -> dict: ...

def brdf(l: numpy.typing.ArrayLike, v: numpy.typing.ArrayLike, *, material: Optional[Material] = None,
         distribution: Optional[str] = None, geometry: Optional[str] = None, fresnel: Optional[str] = None,
         preset: Optional[str] = None, alpha: Optional[float] = None, roughness: Optional[float] = None,
         f0: Optional[Vec3] = None, ior: Optional[Vec3] = None, eta: Optional[Vec3] = None,
         k: Optional[Vec3] = None, diffuse: Optional[Vec3] = None) -> dict[str, numpy.ndarray]: ...
