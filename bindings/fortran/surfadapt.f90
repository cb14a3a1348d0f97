! SPDX-License-Identifier: BSD-3-Clause
!> Fortran binding of surfadapt (see include/surfadapt.h, the contract).
!>
!> Two layers:
!>  - raw bind(C) interfaces, one per C function and under the same name, and every
!>    constant of the header under the same name. A host passes its own (3,n) arrays
!>    straight to the assumed-size dummies, e.g.
!>        rc = sfa_set_mesh(s, nv, xyz, nt, tri, 1)
!>    with xyz(3,nv) and tri(3,nt) holding 1-based vertex indices;
!>  - a few wrappers with their own names (sfa_version, sfa_status_message,
!>    sfa_error_message, sfa_get_mesh_alloc, sfa_get_field_alloc,
!>    sfa_get_feature_ranks_alloc) that return Fortran strings and allocatable arrays.
!>
!> Handles are type(c_ptr): create with sfa_create, free with sfa_destroy. Units are the
!> host's own, as in C. Status codes are integer(c_int), SFA_OK == 0.
module surfadapt
  use, intrinsic :: iso_c_binding, only: c_int, c_int32_t, c_int64_t, c_double, c_ptr, &
       c_funptr, c_char, c_size_t, c_associated, c_f_pointer, c_null_ptr
  implicit none
  private

  ! ------------------------------------------------------------------ versions
  integer(c_int), parameter, public :: SFA_VERSION_MAJOR = 1
  integer(c_int), parameter, public :: SFA_VERSION_MINOR = 1
  integer(c_int), parameter, public :: SFA_VERSION_PATCH = 0
  ! The header's SFA_ABI_VERSION, renamed: Fortran names are case-insensitive, so it
  ! would clash with the function sfa_abi_version.
  integer(c_int), parameter, public :: SFA_HEADER_ABI_VERSION = 1

  ! ------------------------------------------------------------ enum sfa_status
  integer(c_int), parameter, public :: SFA_OK = 0
  integer(c_int), parameter, public :: SFA_ERR_ARGUMENT = 1
  integer(c_int), parameter, public :: SFA_ERR_MESH = 2
  integer(c_int), parameter, public :: SFA_ERR_STATE = 3
  integer(c_int), parameter, public :: SFA_ERR_NUMERIC = 4
  integer(c_int), parameter, public :: SFA_ERR_MEMORY = 5
  integer(c_int), parameter, public :: SFA_ERR_INTERNAL = 6

  ! ------------------------------------------------------------- enum sfa_param
  ! Meanings, units and ranges: see enum sfa_param in surfadapt.h.
  integer(c_int), parameter, public :: SFA_PARAM_EDGE_LENGTH = 0
  integer(c_int), parameter, public :: SFA_PARAM_ANISOTROPIC = 1
  integer(c_int), parameter, public :: SFA_PARAM_RIDGE_ANGLE = 2
  integer(c_int), parameter, public :: SFA_PARAM_CORNER_ANGLE = 3
  integer(c_int), parameter, public :: SFA_PARAM_METRIC_MIN_ANGLE = 4
  integer(c_int), parameter, public :: SFA_PARAM_METRIC_MAX_ANGLE = 5
  integer(c_int), parameter, public :: SFA_PARAM_SPLIT_LENGTH_RATIO = 6
  integer(c_int), parameter, public :: SFA_PARAM_SPLIT_SHORTEST_RATIO = 7
  integer(c_int), parameter, public :: SFA_PARAM_CONTRACT_LENGTH_RATIO = 8
  integer(c_int), parameter, public :: SFA_PARAM_CONTRACT_SHORT_RATIO = 9
  integer(c_int), parameter, public :: SFA_PARAM_CONTRACT_SMALL_RATIO = 10
  integer(c_int), parameter, public :: SFA_PARAM_SMALL_ANGLE = 11
  integer(c_int), parameter, public :: SFA_PARAM_LARGE_ANGLE = 12
  integer(c_int), parameter, public :: SFA_PARAM_FOLD_SAFETY = 13
  integer(c_int), parameter, public :: SFA_PARAM_DROP_UNREFERENCED = 14
  integer(c_int), parameter, public :: SFA_PARAM_RIDGE_TURN_ANGLE = 15
  integer(c_int), parameter, public :: SFA_PARAM_FLIP_DIHEDRAL_ANGLE = 16
  integer(c_int), parameter, public :: SFA_PARAM_THREADS = 17
  integer(c_int), parameter, public :: SFA_PARAM_DENOISE = 18
  integer(c_int), parameter, public :: SFA_PARAM_ADAPT_PASSES = 19
  integer(c_int), parameter, public :: SFA_PARAM_CROSSING_GUARD = 20
  integer(c_int), parameter, public :: SFA_PARAM_VOLUME_CORRECTION = 21
  integer(c_int), parameter, public :: SFA_PARAM_SIZE_GRADATION = 22
  integer(c_int), parameter, public :: SFA_PARAM_SHORT_EDGE_RATIO = 23
  integer(c_int), parameter, public :: SFA_PARAM_COLLISION_SAFE_MOTION = 24
  integer(c_int), parameter, public :: SFA_PARAM_TOPOLOGY_CHANGE = 25
  integer(c_int), parameter, public :: SFA_PARAM_MERGE_DISTANCE = 26
  integer(c_int), parameter, public :: SFA_PARAM_THIN_SHEET_EDGE_RATIO = 27

  ! --------------------------------------------------- enum sfa_measure_quantity
  integer(c_int), parameter, public :: SFA_MEASURE_VOLUME = 0
  integer(c_int), parameter, public :: SFA_MEASURE_AREA = 1
  integer(c_int), parameter, public :: SFA_MEASURE_MIN_ANGLE = 2
  integer(c_int), parameter, public :: SFA_MEASURE_MAX_ANGLE = 3
  integer(c_int), parameter, public :: SFA_MEASURE_MEAN_EDGE_LENGTH = 4
  integer(c_int), parameter, public :: SFA_MEASURE_MAX_ASPECT_RATIO = 5
  integer(c_int), parameter, public :: SFA_MEASURE_MIN_EDGE_LENGTH = 6
  integer(c_int), parameter, public :: SFA_MEASURE_MAX_EDGE_LENGTH = 7
  integer(c_int), parameter, public :: SFA_MEASURE_MAX_NORMAL_TURN = 8
  integer(c_int), parameter, public :: SFA_MEASURE_SECONDS_ANALYSIS = 9
  integer(c_int), parameter, public :: SFA_MEASURE_SECONDS_SMOOTHING = 10
  integer(c_int), parameter, public :: SFA_MEASURE_SECONDS_FLIPPING = 11
  integer(c_int), parameter, public :: SFA_MEASURE_SECONDS_REPAIR = 12
  integer(c_int), parameter, public :: SFA_MEASURE_SELF_INTERSECTIONS = 13
  integer(c_int), parameter, public :: SFA_MEASURE_VOLUME_CORRECTION = 14
  integer(c_int), parameter, public :: SFA_MEASURE_MERGES = 15
  integer(c_int), parameter, public :: SFA_MEASURE_PINCHES = 16
  integer(c_int), parameter, public :: SFA_MEASURE_TOPOLOGY_VOLUME_CHANGE = 17
  integer(c_int), parameter, public :: SFA_MEASURE_DROPS_REMOVED = 18
  integer(c_int), parameter, public :: SFA_MEASURE_VOLUME_LEFT = 19
  integer(c_int), parameter, public :: SFA_MEASURE_UNRESOLVED_AREA = 20
  integer(c_int), parameter, public :: SFA_MEASURE_MIN_ANGLE_RESOLVED = 21

  public :: sfa_version_string, sfa_abi_version, sfa_version_number, sfa_status_string
  public :: sfa_create, sfa_destroy, sfa_last_error
  public :: sfa_set_mesh, sfa_get_counts, sfa_get_mesh
  public :: sfa_set_param, sfa_get_param, sfa_get_param_bounds
  public :: sfa_set_velocities, sfa_move, sfa_advect
  public :: sfa_smooth, sfa_adapt
  public :: sfa_get_feature_ranks, sfa_measure
  public :: sfa_get_component_count, sfa_get_components, sfa_measure_component
  public :: sfa_add_field, sfa_get_field, sfa_set_field
  public :: sfa_set_velocities_checked, sfa_add_field_checked
  public :: sfa_set_size_field, sfa_set_size_field_checked, sfa_clear_size_field
  public :: sfa_set_fixed_vertices, sfa_set_required_edges
  public :: sfa_add_face_field, sfa_add_face_field_checked, sfa_get_face_field, sfa_set_face_field
  public :: sfa_get_vertex_origins
  public :: sfa_get_vertex_frames, sfa_get_ridge_edges
  public :: sfa_get_api

  public :: sfa_version, sfa_status_message, sfa_error_message
  public :: sfa_get_mesh_alloc, sfa_get_field_alloc, sfa_get_feature_ranks_alloc

  ! --------------------------------------------------------- raw C interfaces
  ! Strings come back as type(c_ptr) because a bind(C) function cannot return a
  ! character string; the wrappers convert them. The velocity callback given to
  ! sfa_advect is c_funloc of a procedure with this interface:
  !   subroutine velocity(ctx, n, xyz, t, vel) bind(C)
  !     type(c_ptr), value :: ctx
  !     integer(c_int32_t), value :: n
  !     real(c_double), intent(in) :: xyz(3, n)
  !     real(c_double), value :: t
  !     real(c_double), intent(out) :: vel(3, n)
  interface
    !> "MAJOR.MINOR.PATCH", a static C string.
    function sfa_version_string() bind(C, name='sfa_version_string')
      import :: c_ptr
      type(c_ptr) :: sfa_version_string
    end function sfa_version_string

    function sfa_abi_version() bind(C, name='sfa_abi_version')
      import :: c_int
      integer(c_int) :: sfa_abi_version
    end function sfa_abi_version

    !> MAJOR * 10000 + MINOR * 100 + PATCH of the library loaded.
    function sfa_version_number() bind(C, name='sfa_version_number')
      import :: c_int
      integer(c_int) :: sfa_version_number
    end function sfa_version_number

    !> A static, never null C string describing a status code.
    function sfa_status_string(status) bind(C, name='sfa_status_string')
      import :: c_int, c_ptr
      integer(c_int), value :: status
      type(c_ptr) :: sfa_status_string
    end function sfa_status_string

    function sfa_create(out) bind(C, name='sfa_create')
      import :: c_int, c_ptr
      type(c_ptr), intent(out) :: out
      integer(c_int) :: sfa_create
    end function sfa_create

    subroutine sfa_destroy(s) bind(C, name='sfa_destroy')
      import :: c_ptr
      type(c_ptr), value :: s
    end subroutine sfa_destroy

    !> A C string owned by s, valid until the next call on s.
    function sfa_last_error(s) bind(C, name='sfa_last_error')
      import :: c_ptr
      type(c_ptr), value :: s
      type(c_ptr) :: sfa_last_error
    end function sfa_last_error

    function sfa_set_mesh(s, nverts, xyz, ntris, tris, index_base) bind(C, name='sfa_set_mesh')
      import :: c_int, c_int32_t, c_double, c_ptr
      type(c_ptr), value :: s
      integer(c_int32_t), value :: nverts
      real(c_double), intent(in) :: xyz(*)
      integer(c_int32_t), value :: ntris
      integer(c_int32_t), intent(in) :: tris(*)
      integer(c_int32_t), value :: index_base
      integer(c_int) :: sfa_set_mesh
    end function sfa_set_mesh

    function sfa_get_counts(s, nverts, ntris) bind(C, name='sfa_get_counts')
      import :: c_int, c_int32_t, c_ptr
      type(c_ptr), value :: s
      integer(c_int32_t), intent(out) :: nverts, ntris
      integer(c_int) :: sfa_get_counts
    end function sfa_get_counts

    function sfa_get_mesh(s, vert_capacity, xyz, tri_capacity, tris, index_base) &
         bind(C, name='sfa_get_mesh')
      import :: c_int, c_int32_t, c_double, c_ptr
      type(c_ptr), value :: s
      integer(c_int32_t), value :: vert_capacity
      real(c_double), intent(out) :: xyz(*)
      integer(c_int32_t), value :: tri_capacity
      integer(c_int32_t), intent(out) :: tris(*)
      integer(c_int32_t), value :: index_base
      integer(c_int) :: sfa_get_mesh
    end function sfa_get_mesh

    function sfa_set_param(s, key, value) bind(C, name='sfa_set_param')
      import :: c_int, c_double, c_ptr
      type(c_ptr), value :: s
      integer(c_int), value :: key
      real(c_double), value :: value
      integer(c_int) :: sfa_set_param
    end function sfa_set_param

    function sfa_get_param(s, key, value) bind(C, name='sfa_get_param')
      import :: c_int, c_double, c_ptr
      type(c_ptr), value :: s
      integer(c_int), value :: key
      real(c_double), intent(out) :: value
      integer(c_int) :: sfa_get_param
    end function sfa_get_param

    !> The ends [lowest, highest] of the values sfa_set_param accepts for key, in its unit;
    !> an end that the key's range leaves open is given but not itself accepted, and an
    !> unbounded end is +infinity (ieee_is_finite tells). No handle, so no error message:
    !> an unknown key gives SFA_ERR_ARGUMENT and leaves lowest and highest undefined.
    function sfa_get_param_bounds(key, lowest, highest) bind(C, name='sfa_get_param_bounds')
      import :: c_int, c_double
      integer(c_int), value :: key
      real(c_double), intent(out) :: lowest, highest
      integer(c_int) :: sfa_get_param_bounds
    end function sfa_get_param_bounds

    function sfa_set_velocities(s, vel) bind(C, name='sfa_set_velocities')
      import :: c_int, c_double, c_ptr
      type(c_ptr), value :: s
      real(c_double), intent(in) :: vel(*)
      integer(c_int) :: sfa_set_velocities
    end function sfa_set_velocities

    function sfa_move(s, dt, dt_taken) bind(C, name='sfa_move')
      import :: c_int, c_double, c_ptr
      type(c_ptr), value :: s
      real(c_double), value :: dt
      real(c_double), intent(out) :: dt_taken
      integer(c_int) :: sfa_move
    end function sfa_move

    function sfa_advect(s, f, ctx, t, dt, dt_taken) bind(C, name='sfa_advect')
      import :: c_int, c_double, c_ptr, c_funptr
      type(c_ptr), value :: s
      type(c_funptr), value :: f
      type(c_ptr), value :: ctx
      real(c_double), value :: t
      real(c_double), value :: dt
      real(c_double), intent(out) :: dt_taken
      integer(c_int) :: sfa_advect
    end function sfa_advect

    function sfa_smooth(s, iterations) bind(C, name='sfa_smooth')
      import :: c_int, c_int32_t, c_ptr
      type(c_ptr), value :: s
      integer(c_int32_t), value :: iterations
      integer(c_int) :: sfa_smooth
    end function sfa_smooth

    function sfa_adapt(s) bind(C, name='sfa_adapt')
      import :: c_int, c_ptr
      type(c_ptr), value :: s
      integer(c_int) :: sfa_adapt
    end function sfa_adapt

    function sfa_get_feature_ranks(s, capacity, ranks) bind(C, name='sfa_get_feature_ranks')
      import :: c_int, c_int32_t, c_ptr
      type(c_ptr), value :: s
      integer(c_int32_t), value :: capacity
      integer(c_int32_t), intent(out) :: ranks(*)
      integer(c_int) :: sfa_get_feature_ranks
    end function sfa_get_feature_ranks

    function sfa_measure(s, quantity, value) bind(C, name='sfa_measure')
      import :: c_int, c_double, c_ptr
      type(c_ptr), value :: s
      integer(c_int), value :: quantity
      real(c_double), intent(out) :: value
      integer(c_int) :: sfa_measure
    end function sfa_measure

    !> The number of connected components (bubbles, drops, sheets) of the current mesh.
    function sfa_get_component_count(s, count) bind(C, name='sfa_get_component_count')
      import :: c_ptr, c_int, c_int32_t
      type(c_ptr), value :: s
      integer(c_int32_t), intent(out) :: count
      integer(c_int) :: sfa_get_component_count
    end function sfa_get_component_count

    !> The component of each vertex, 0 to count - 1 (0-based whatever the index base).
    function sfa_get_components(s, capacity, vertex_component) bind(C, name='sfa_get_components')
      import :: c_ptr, c_int, c_int32_t
      type(c_ptr), value :: s
      integer(c_int32_t), value :: capacity
      integer(c_int32_t), intent(out) :: vertex_component(*)
      integer(c_int) :: sfa_get_components
    end function sfa_get_components

    !> sfa_measure restricted to one component (0-based, as sfa_get_components numbers them).
    function sfa_measure_component(s, component, quantity, value) bind(C, name='sfa_measure_component')
      import :: c_ptr, c_int, c_int32_t, c_double
      type(c_ptr), value :: s
      integer(c_int32_t), value :: component
      integer(c_int), value :: quantity
      real(c_double), intent(out) :: value
      integer(c_int) :: sfa_measure_component
    end function sfa_measure_component

    function sfa_add_field(s, ncomp, values, field_id) bind(C, name='sfa_add_field')
      import :: c_int, c_int32_t, c_double, c_ptr
      type(c_ptr), value :: s
      integer(c_int32_t), value :: ncomp
      real(c_double), intent(in) :: values(*)
      integer(c_int32_t), intent(out) :: field_id
      integer(c_int) :: sfa_add_field
    end function sfa_add_field

    !> The checked variants take the number of vertices the host's array was made for,
    !> and refuse an array made for another mesh (SFA_ERR_ARGUMENT).
    function sfa_add_field_checked(s, nverts, ncomp, values, field_id) bind(C, name='sfa_add_field_checked')
      import :: c_int, c_int32_t, c_double, c_ptr
      type(c_ptr), value :: s
      integer(c_int32_t), value :: nverts, ncomp
      real(c_double), intent(in) :: values(*)
      integer(c_int32_t), intent(out) :: field_id
      integer(c_int) :: sfa_add_field_checked
    end function sfa_add_field_checked

    function sfa_set_velocities_checked(s, nverts, vel) bind(C, name='sfa_set_velocities_checked')
      import :: c_int, c_int32_t, c_double, c_ptr
      type(c_ptr), value :: s
      integer(c_int32_t), value :: nverts
      real(c_double), intent(in) :: vel(*)
      integer(c_int) :: sfa_set_velocities_checked
    end function sfa_set_velocities_checked

    !> One desired edge length per vertex (host units, > 0); sfa_clear_size_field clears it.
    function sfa_set_size_field(s, edge_length) bind(C, name='sfa_set_size_field')
      import :: c_int, c_double, c_ptr
      type(c_ptr), value :: s
      real(c_double), intent(in) :: edge_length(*)
      integer(c_int) :: sfa_set_size_field
    end function sfa_set_size_field

    function sfa_set_size_field_checked(s, nverts, edge_length) bind(C, name='sfa_set_size_field_checked')
      import :: c_int, c_int32_t, c_double, c_ptr
      type(c_ptr), value :: s
      integer(c_int32_t), value :: nverts
      real(c_double), intent(in) :: edge_length(*)
      integer(c_int) :: sfa_set_size_field_checked
    end function sfa_set_size_field_checked

    !> index_base 1 for Fortran numbering; count 0 clears.
    function sfa_set_fixed_vertices(s, count, vertices, index_base) bind(C, name='sfa_set_fixed_vertices')
      import :: c_int, c_int32_t, c_ptr
      type(c_ptr), value :: s
      integer(c_int32_t), value :: count
      integer(c_int32_t), intent(in) :: vertices(*)
      integer(c_int32_t), value :: index_base
      integer(c_int) :: sfa_set_fixed_vertices
    end function sfa_set_fixed_vertices

    !> edges(2, count): the two ends of each required edge; count 0 clears.
    function sfa_set_required_edges(s, count, edges, index_base) bind(C, name='sfa_set_required_edges')
      import :: c_int, c_int32_t, c_ptr
      type(c_ptr), value :: s
      integer(c_int32_t), value :: count
      integer(c_int32_t), intent(in) :: edges(*)
      integer(c_int32_t), value :: index_base
      integer(c_int) :: sfa_set_required_edges
    end function sfa_set_required_edges

    !> Densities per unit area on the triangles, values(ncomp, ntris); the integral of each
    !> component over each surface component is kept by sfa_smooth and sfa_adapt.
    function sfa_add_face_field(s, ncomp, values, field_id) bind(C, name='sfa_add_face_field')
      import :: c_int, c_int32_t, c_double, c_ptr
      type(c_ptr), value :: s
      integer(c_int32_t), value :: ncomp
      real(c_double), intent(in) :: values(*)
      integer(c_int32_t), intent(out) :: field_id
      integer(c_int) :: sfa_add_face_field
    end function sfa_add_face_field

    function sfa_add_face_field_checked(s, ntris, ncomp, values, field_id) &
         bind(C, name='sfa_add_face_field_checked')
      import :: c_int, c_int32_t, c_double, c_ptr
      type(c_ptr), value :: s
      integer(c_int32_t), value :: ntris, ncomp
      real(c_double), intent(in) :: values(*)
      integer(c_int32_t), intent(out) :: field_id
      integer(c_int) :: sfa_add_face_field_checked
    end function sfa_add_face_field_checked

    function sfa_get_face_field(s, field_id, capacity, values) bind(C, name='sfa_get_face_field')
      import :: c_int, c_int32_t, c_double, c_ptr
      type(c_ptr), value :: s
      integer(c_int32_t), value :: field_id, capacity
      real(c_double), intent(out) :: values(*)
      integer(c_int) :: sfa_get_face_field
    end function sfa_get_face_field

    !> Replaces a face field's densities (ncomp*ntris, ntris the mesh's triangle count).
    function sfa_set_face_field(s, field_id, ntris, values) bind(C, name='sfa_set_face_field')
      import :: c_int, c_int32_t, c_double, c_ptr
      type(c_ptr), value :: s
      integer(c_int32_t), value :: field_id, ntris
      real(c_double), intent(in) :: values(*)
      integer(c_int) :: sfa_set_face_field
    end function sfa_set_face_field

    !> For each vertex, the triangle of the mesh before the last sfa_smooth/sfa_adapt it lay
    !> over (triangle(nverts), from index_base) and its coordinates there (barycentric(3, nverts)).
    function sfa_get_vertex_origins(s, capacity, triangle, barycentric, index_base) &
         bind(C, name='sfa_get_vertex_origins')
      import :: c_int, c_int32_t, c_double, c_ptr
      type(c_ptr), value :: s
      integer(c_int32_t), value :: capacity
      integer(c_int32_t), intent(out) :: triangle(*)
      real(c_double), intent(out) :: barycentric(*)
      integer(c_int32_t), value :: index_base
      integer(c_int) :: sfa_get_vertex_origins
    end function sfa_get_vertex_origins

    function sfa_get_field(s, field_id, capacity, values) bind(C, name='sfa_get_field')
      import :: c_int, c_int32_t, c_double, c_ptr
      type(c_ptr), value :: s
      integer(c_int32_t), value :: field_id
      integer(c_int32_t), value :: capacity
      real(c_double), intent(out) :: values(*)
      integer(c_int) :: sfa_get_field
    end function sfa_get_field

    !> Replaces a field's values (ncomp*nverts, nverts the mesh's vertex count).
    function sfa_set_field(s, field_id, nverts, values) bind(C, name='sfa_set_field')
      import :: c_int, c_int32_t, c_double, c_ptr
      type(c_ptr), value :: s
      integer(c_int32_t), value :: field_id, nverts
      real(c_double), intent(in) :: values(*)
      integer(c_int) :: sfa_set_field
    end function sfa_set_field

    !> Per-vertex normals (3,n), long directions (3,n) and metric aspect ratios (n).
    !> The C function accepts NULL for outputs not wanted; this interface asks for all three.
    function sfa_get_vertex_frames(s, capacity, normals, long_directions, aspect_ratios) &
        bind(C, name='sfa_get_vertex_frames')
      import :: c_int, c_int32_t, c_double, c_ptr
      type(c_ptr), value :: s
      integer(c_int32_t), value :: capacity
      real(c_double), intent(out) :: normals(*), long_directions(*), aspect_ratios(*)
      integer(c_int) :: sfa_get_vertex_frames
    end function sfa_get_vertex_frames

    !> Ridge edges as vertex pairs edges(2,count) in index_base. count is always written;
    !> with capacity 0 the call returns SFA_ERR_ARGUMENT (if there are ridge edges) and
    !> only count, which is how to size the array.
    function sfa_get_ridge_edges(s, capacity, edges, count, index_base) bind(C, name='sfa_get_ridge_edges')
      import :: c_int, c_int32_t, c_ptr
      type(c_ptr), value :: s
      integer(c_int32_t), value :: capacity
      integer(c_int32_t), intent(out) :: edges(*)
      integer(c_int32_t), intent(out) :: count
      integer(c_int32_t), value :: index_base
      integer(c_int) :: sfa_get_ridge_edges
    end function sfa_get_ridge_edges

    !> Pointer to the const sfa_api table, or c_null_ptr. The C argument is uint32_t;
    !> Fortran has no unsigned kind, and int32_t is passed the same way for the values
    !> that exist (small positive versions).
    function sfa_get_api(abi_version) bind(C, name='sfa_get_api')
      import :: c_int32_t, c_ptr
      integer(c_int32_t), value :: abi_version
      type(c_ptr) :: sfa_get_api
    end function sfa_get_api
  end interface

  ! Only to measure C strings before copying them.
  interface
    function c_strlen(str) bind(C, name='strlen')
      import :: c_ptr, c_size_t
      type(c_ptr), value :: str
      integer(c_size_t) :: c_strlen
    end function c_strlen

    ! sfa_set_size_field with a pointer argument, so that NULL (clear) can be passed.
    function sfa_set_size_field_ptr(s, edge_length) bind(C, name='sfa_set_size_field')
      import :: c_int, c_ptr
      type(c_ptr), value :: s
      type(c_ptr), value :: edge_length
      integer(c_int) :: sfa_set_size_field_ptr
    end function sfa_set_size_field_ptr
  end interface

contains

  ! Copies a NUL-terminated C string into a Fortran string; a null pointer gives "".
  function from_c_string(p) result(str)
    type(c_ptr), intent(in) :: p
    character(len=:), allocatable :: str
    character(kind=c_char), pointer :: chars(:)
    integer :: n, i

    if (.not. c_associated(p)) then
      str = ''
      return
    end if
    n = int(c_strlen(p))
    call c_f_pointer(p, chars, [n])
    allocate(character(len=n) :: str)
    do i = 1, n
      str(i:i) = chars(i)
    end do
  end function from_c_string

  !> The library version, "MAJOR.MINOR.PATCH", as a Fortran string (a copy).
  function sfa_version() result(str)
    character(len=:), allocatable :: str
    str = from_c_string(sfa_version_string())
  end function sfa_version

  !> Description of a status code, e.g. "SFA_ERR_MESH: ..." (a copy; never empty).
  function sfa_status_message(status) result(str)
    integer(c_int), intent(in) :: status
    character(len=:), allocatable :: str
    str = from_c_string(sfa_status_string(status))
  end function sfa_status_message

  !> Why the last call on s failed, naming the offending input in the index base the
  !> host used; "" after a successful call. A copy, so it stays valid after further calls.
  function sfa_error_message(s) result(str)
    type(c_ptr), intent(in) :: s
    character(len=:), allocatable :: str
    str = from_c_string(sfa_last_error(s))
  end function sfa_error_message

  !> Copies the current mesh into newly allocated arrays xyz(3,nverts) (host length
  !> units) and tris(3,ntris) (vertex indices in index_base, default 1 so that they
  !> index xyz(:,i) directly). The arrays belong to the caller. Returns a status; on
  !> failure both arrays are left unallocated and sfa_error_message(s) says why.
  function sfa_get_mesh_alloc(s, xyz, tris, index_base) result(rc)
    type(c_ptr), intent(in) :: s
    real(c_double), allocatable, intent(out) :: xyz(:, :)
    integer(c_int32_t), allocatable, intent(out) :: tris(:, :)
    integer(c_int32_t), intent(in), optional :: index_base
    integer(c_int) :: rc
    integer(c_int32_t) :: nv, nt, base

    base = 1
    if (present(index_base)) base = index_base
    rc = sfa_get_counts(s, nv, nt)
    if (rc /= SFA_OK) return
    allocate(xyz(3, nv), tris(3, nt))
    rc = sfa_get_mesh(s, nv, xyz, nt, tris, base)
    if (rc /= SFA_OK) deallocate(xyz, tris)
  end function sfa_get_mesh_alloc

  !> Copies field field_id (an id from sfa_add_field) into a newly allocated
  !> values(ncomp,nverts), values(c,i) being component c of vertex i. The C API keeps no
  !> record a host can query of a field's width, so ncomp must be the value given to
  !> sfa_add_field. The array belongs to the caller. Returns a status; on failure values
  !> is left unallocated. ncomp < 1, or a field too large for int32 capacities, gives
  !> SFA_ERR_ARGUMENT without calling the library (sfa_error_message is then not updated).
  function sfa_get_field_alloc(s, field_id, ncomp, values) result(rc)
    type(c_ptr), intent(in) :: s
    integer(c_int32_t), intent(in) :: field_id
    integer(c_int32_t), intent(in) :: ncomp
    real(c_double), allocatable, intent(out) :: values(:, :)
    integer(c_int) :: rc
    integer(c_int32_t) :: nv, nt

    rc = sfa_get_counts(s, nv, nt)
    if (rc /= SFA_OK) return
    if (ncomp < 1 .or. int(ncomp, c_int64_t) * nv > huge(nv)) then
      rc = SFA_ERR_ARGUMENT
      return
    end if
    allocate(values(ncomp, nv))
    rc = sfa_get_field(s, field_id, ncomp * nv, values)
    if (rc /= SFA_OK) deallocate(values)
  end function sfa_get_field_alloc

  !> Feature rank of every current vertex in a newly allocated ranks(nverts):
  !> 0 smooth, 1 ridge, 2 corner. The array belongs to the caller. Returns a status;
  !> on failure ranks is left unallocated.
  function sfa_get_feature_ranks_alloc(s, ranks) result(rc)
    type(c_ptr), intent(in) :: s
    integer(c_int32_t), allocatable, intent(out) :: ranks(:)
    integer(c_int) :: rc
    integer(c_int32_t) :: nv, nt

    rc = sfa_get_counts(s, nv, nt)
    if (rc /= SFA_OK) return
    allocate(ranks(nv))
    rc = sfa_get_feature_ranks(s, nv, ranks)
    if (rc /= SFA_OK) deallocate(ranks)
  end function sfa_get_feature_ranks_alloc

  !> Clears the size field (sfa_set_size_field(s, NULL) in C): SFA_PARAM_EDGE_LENGTH
  !> applies everywhere again. Returns a status.
  function sfa_clear_size_field(s) result(rc)
    type(c_ptr), intent(in) :: s
    integer(c_int) :: rc
    rc = sfa_set_size_field_ptr(s, c_null_ptr)
  end function sfa_clear_size_field

end module surfadapt
