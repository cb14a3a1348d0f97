! SPDX-License-Identifier: BSD-3-Clause
! Test of the Fortran binding: a host with 1-based (3,n) arrays drives the library
! through the module surfadapt. Prints one line per check and a final summary line;
! stops with a non-zero status if any check failed.

! Check bookkeeping and the velocity field given to sfa_advect.
module test_support
  use, intrinsic :: iso_c_binding, only: c_int32_t, c_double, c_ptr, c_f_pointer
  implicit none
  private
  public :: check, near, max_abs_diff, rotate_z
  public :: npass, nfail, ncalls, last_n, tmin, tmax

  integer, save :: npass = 0, nfail = 0
  ! What the library handed to rotate_z, to check the callback protocol.
  integer, save :: ncalls = 0
  integer(c_int32_t), save :: last_n = -1
  real(c_double), save :: tmin = huge(1.0_c_double), tmax = -huge(1.0_c_double)

contains

  subroutine check(name, ok, detail)
    character(len=*), intent(in) :: name
    logical, intent(in) :: ok
    character(len=*), intent(in), optional :: detail

    if (ok) then
      npass = npass + 1
      write(*, '(a)') 'PASS ' // name
    else
      nfail = nfail + 1
      if (present(detail)) then
        write(*, '(a)') 'FAIL ' // name // ': ' // detail
      else
        write(*, '(a)') 'FAIL ' // name
      end if
    end if
  end subroutine check

  ! Real comparisons go through a tolerance (0 for exact) rather than ==.
  logical function near(a, b, tol)
    real(c_double), intent(in) :: a, b, tol
    near = abs(a - b) <= tol
  end function near

  real(c_double) function max_abs_diff(a, b)
    real(c_double), intent(in) :: a(:, :), b(:, :)
    max_abs_diff = maxval(abs(a - b))
  end function max_abs_diff

  ! Rigid rotation about the z axis, v = omega e_z x x, omega read through ctx.
  subroutine rotate_z(ctx, n, xyz, t, vel) bind(C)
    type(c_ptr), value :: ctx
    integer(c_int32_t), value :: n
    real(c_double), intent(in) :: xyz(3, n)
    real(c_double), value :: t
    real(c_double), intent(out) :: vel(3, n)
    real(c_double), pointer :: omega

    call c_f_pointer(ctx, omega)
    ncalls = ncalls + 1
    last_n = n
    tmin = min(tmin, t)
    tmax = max(tmax, t)
    vel(1, :) = -omega * xyz(2, :)
    vel(2, :) = omega * xyz(1, :)
    vel(3, :) = 0.0_c_double
  end subroutine rotate_z

end module test_support

program test_surfadapt
  use, intrinsic :: iso_c_binding, only: c_int, c_int32_t, c_double, c_ptr, c_null_ptr, &
       c_associated, c_f_pointer, c_funloc, c_loc, c_sizeof, c_null_funptr
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  use surfadapt
  use test_support
  implicit none

  real(c_double), parameter :: eps = epsilon(1.0_c_double)
  integer(c_int32_t), parameter :: nv = 8, nt = 12

  ! Unit cube [0,1]^3, triangles counter-clockwise seen from outside, 1-based.
  real(c_double), parameter :: cube_xyz(3, nv) = reshape([ &
       0, 0, 0,   1, 0, 0,   1, 1, 0,   0, 1, 0, &
       0, 0, 1,   1, 0, 1,   1, 1, 1,   0, 1, 1], [3, 8]) * 1.0_c_double
  integer(c_int32_t), parameter :: cube_tri(3, nt) = reshape([ &
       1, 3, 2,   1, 4, 3, &   ! z = 0
       5, 6, 7,   5, 7, 8, &   ! z = 1
       1, 2, 6,   1, 6, 5, &   ! y = 0
       4, 8, 7,   4, 7, 3, &   ! y = 1
       1, 5, 8,   1, 8, 4, &   ! x = 0
       2, 3, 7,   2, 7, 6],  & ! x = 1
       [3, 12])

  type(c_ptr) :: s, api
  integer(c_int) :: rc
  integer(c_int32_t) :: nverts, ntris, field_id, i
  integer(c_int32_t), pointer :: api_head(:)
  integer(c_int32_t), allocatable :: tri_out(:, :), ranks(:)
  integer(c_int32_t) :: vranks(nv), vcomponents(nv), ncomponents
  integer(c_int32_t) :: bad_tri(3, nt), small_tri(3, 1)
  real(c_double) :: value, volume_before, dt, dt_taken, t0, theta, c, sn, lowest, highest
  real(c_double) :: vel(3, nv), before(3, nv), expected(3, nv), small_xyz(3, 1)
  real(c_double) :: field(2, nv)
  real(c_double), target :: omega
  real(c_double), allocatable :: xyz_out(:, :), field_out(:, :), sizes(:), stale(:, :)
  integer(c_int32_t) :: fixed(1), pinned(2, 1)
  integer(c_int32_t), allocatable :: origin_tri(:)
  real(c_double), allocatable :: origin_w(:, :), densities(:)
  real(c_double) :: fixed_at(3)
  character(len=32) :: want_version
  character(len=:), allocatable :: msg

  ! ------------------------------------------------------------ library
  write(want_version, '(i0,".",i0,".",i0)') SFA_VERSION_MAJOR, SFA_VERSION_MINOR, &
       SFA_VERSION_PATCH
  call check('sfa_version is "' // trim(want_version) // '"', &
       sfa_version() == trim(want_version), 'got "' // sfa_version() // '"')
  call check('sfa_abi_version == SFA_HEADER_ABI_VERSION', &
       sfa_abi_version() == SFA_HEADER_ABI_VERSION)
  call check('sfa_version_number is MAJOR * 10000 + MINOR * 100 + PATCH', &
       sfa_version_number() == SFA_VERSION_MAJOR * 10000 + SFA_VERSION_MINOR * 100 + SFA_VERSION_PATCH)

  ! Bounds need no handle: (0, 180) for an angle, [0, +infinity) for the edge length.
  rc = sfa_get_param_bounds(SFA_PARAM_RIDGE_ANGLE, lowest, highest)
  call check('sfa_get_param_bounds(SFA_PARAM_RIDGE_ANGLE) gives 0 and 180', rc == SFA_OK .and. &
       near(lowest, 0.0_c_double, 0.0_c_double) .and. near(highest, 180.0_c_double, 0.0_c_double))
  rc = sfa_get_param_bounds(SFA_PARAM_EDGE_LENGTH, lowest, highest)
  call check('sfa_get_param_bounds(SFA_PARAM_EDGE_LENGTH) gives 0 and +infinity', rc == SFA_OK .and. &
       near(lowest, 0.0_c_double, 0.0_c_double) .and. .not. ieee_is_finite(highest) .and. highest > 0)
  rc = sfa_get_param_bounds(SFA_PARAM_ADAPT_PASSES, lowest, highest)
  call check('sfa_get_param_bounds(SFA_PARAM_ADAPT_PASSES) gives 1 and 100', rc == SFA_OK .and. &
       near(lowest, 1.0_c_double, 0.0_c_double) .and. near(highest, 100.0_c_double, 0.0_c_double))
  rc = sfa_get_param_bounds(1000_c_int, lowest, highest)
  call check('sfa_get_param_bounds of an unknown key gives SFA_ERR_ARGUMENT', rc == SFA_ERR_ARGUMENT)
  call check('sfa_status_message(SFA_ERR_MESH) is not empty', &
       len(sfa_status_message(SFA_ERR_MESH)) > 0)
  call check('sfa_status_message of an unknown code is not empty', &
       len(sfa_status_message(99_c_int)) > 0)

  api = sfa_get_api(int(SFA_HEADER_ABI_VERSION, c_int32_t))
  if (c_associated(api)) then
    ! The table starts with uint32_t struct_size and abi, then 37 function pointers.
    call c_f_pointer(api, api_head, [2])
    call check('sfa_get_api: struct_size covers the 37 functions', &
         api_head(1) >= 8 + 37 * c_sizeof(c_null_funptr))
    call check('sfa_get_api: abi == SFA_HEADER_ABI_VERSION', api_head(2) == SFA_HEADER_ABI_VERSION)
  else
    call check('sfa_get_api(SFA_HEADER_ABI_VERSION) is not null', .false.)
  end if
  call check('sfa_get_api of an unknown ABI is null', &
       .not. c_associated(sfa_get_api(int(SFA_HEADER_ABI_VERSION + 1, c_int32_t))))

  ! ------------------------------------------------------------ lifecycle
  rc = sfa_get_counts(c_null_ptr, nverts, ntris)
  call check('sfa_get_counts(null) gives SFA_ERR_ARGUMENT', rc == SFA_ERR_ARGUMENT)
  call sfa_destroy(c_null_ptr)  ! a no-op by contract; must not crash

  rc = sfa_create(s)
  call check('sfa_create', rc == SFA_OK .and. c_associated(s), sfa_status_message(rc))
  if (.not. c_associated(s)) call finish()

  rc = sfa_get_counts(s, nverts, ntris)
  call check('counts are 0, 0 before a mesh', rc == SFA_OK .and. nverts == 0 .and. ntris == 0)
  rc = sfa_measure(s, SFA_MEASURE_VOLUME, value)
  call check('sfa_measure before a mesh gives SFA_ERR_STATE', rc == SFA_ERR_STATE)

  ! ------------------------------------------------------------ mesh in and out
  rc = sfa_set_mesh(s, nv, cube_xyz, nt, cube_tri, 1)
  call check('sfa_set_mesh(unit cube, index_base 1)', rc == SFA_OK, sfa_error_message(s))
  call check('sfa_error_message is "" after a success', len(sfa_error_message(s)) == 0, &
       '"' // sfa_error_message(s) // '"')

  rc = sfa_get_counts(s, nverts, ntris)
  call check('counts are 8, 12', rc == SFA_OK .and. nverts == nv .and. ntris == nt)

  ! The contract's volume is a sum of a.(b x c)/6 over triangles; 1/6 is not exact in
  ! binary, so allow a few roundings.
  rc = sfa_measure(s, SFA_MEASURE_VOLUME, value)
  call check('volume of the unit cube is 1', rc == SFA_OK .and. near(value, 1.0_c_double, 8 * eps))
  rc = sfa_measure(s, SFA_MEASURE_AREA, value)
  call check('area of the unit cube is 6', rc == SFA_OK .and. near(value, 6.0_c_double, 8 * eps))

  rc = sfa_get_component_count(s, ncomponents)
  call check('the cube is one component', rc == SFA_OK .and. ncomponents == 1)
  rc = sfa_get_components(s, nv, vcomponents)
  call check('every vertex is in component 0', rc == SFA_OK .and. all(vcomponents == 0))
  rc = sfa_measure_component(s, 0, SFA_MEASURE_VOLUME, value)
  call check('component 0 holds the volume 1', rc == SFA_OK .and. near(value, 1.0_c_double, 8 * eps))
  rc = sfa_measure_component(s, 1, SFA_MEASURE_VOLUME, value)
  call check('there is no component 1', rc == SFA_ERR_ARGUMENT)

  rc = sfa_get_mesh_alloc(s, xyz_out, tri_out)
  if (rc == SFA_OK) then
    call check('sfa_get_mesh_alloc: shapes (3,8) and (3,12)', &
         all(shape(xyz_out) == [3, 8]) .and. all(shape(tri_out) == [3, 12]))
    if (all(shape(xyz_out) == [3, 8]) .and. all(shape(tri_out) == [3, 12])) then
      ! Exact: coordinates are copied, not computed.
      call check('mesh read back (index_base 1) equals the input', &
           max_abs_diff(xyz_out, cube_xyz) <= 0 .and. all(tri_out == cube_tri))
    end if
  else
    call check('sfa_get_mesh_alloc', .false., sfa_error_message(s))
  end if
  rc = sfa_get_mesh_alloc(s, xyz_out, tri_out, 0_c_int32_t)
  if (rc == SFA_OK) then
    call check('sfa_get_mesh_alloc(index_base 0) gives 0-based indices', &
         all(tri_out + 1 == cube_tri))
  else
    call check('sfa_get_mesh_alloc(index_base 0)', .false., sfa_error_message(s))
  end if

  small_xyz = -7
  small_tri = -7
  rc = sfa_get_mesh(s, 1_c_int32_t, small_xyz, 1_c_int32_t, small_tri, 1_c_int32_t)
  call check('sfa_get_mesh with too small capacities: SFA_ERR_ARGUMENT, nothing written', &
       rc == SFA_ERR_ARGUMENT .and. all(small_tri == -7) .and. &
       near(maxval(small_xyz), -7.0_c_double, 0.0_c_double) .and. &
       near(minval(small_xyz), -7.0_c_double, 0.0_c_double))

  ! ------------------------------------------------------------ parameters
  rc = sfa_set_param(s, SFA_PARAM_EDGE_LENGTH, 0.25_c_double)
  call check('sfa_set_param(SFA_PARAM_EDGE_LENGTH, 0.25)', rc == SFA_OK, sfa_error_message(s))
  rc = sfa_get_param(s, SFA_PARAM_EDGE_LENGTH, value)
  call check('sfa_get_param(SFA_PARAM_EDGE_LENGTH) gives 0.25', &
       rc == SFA_OK .and. near(value, 0.25_c_double, 0.0_c_double))
  rc = sfa_set_param(s, SFA_PARAM_EDGE_LENGTH, -1.0_c_double)
  call check('a negative edge length gives SFA_ERR_ARGUMENT', rc == SFA_ERR_ARGUMENT)
  rc = sfa_get_param(s, SFA_PARAM_EDGE_LENGTH, value)
  call check('the rejected value left the parameter as it was', &
       rc == SFA_OK .and. near(value, 0.25_c_double, 0.0_c_double))

  ! ------------------------------------------------------------ a bad mesh
  bad_tri = cube_tri
  bad_tri(3, 5) = 9  ! vertex 9 of 8, counted from 1
  rc = sfa_set_mesh(s, nv, cube_xyz, nt, bad_tri, 1)
  msg = sfa_error_message(s)
  call check('index 9 on 8 vertices gives SFA_ERR_MESH', rc == SFA_ERR_MESH, &
       sfa_status_message(rc))
  call check('the error message is not empty', len(msg) > 0)
  call check('the error message names vertex 9 (host index base)', index(msg, '9') > 0, &
       '"' // msg // '"')
  write(*, '(a)') '  message: ' // msg
  rc = sfa_get_counts(s, nverts, ntris)
  call check('the cube is still there: counts 8, 12', &
       rc == SFA_OK .and. nverts == nv .and. ntris == nt)
  rc = sfa_measure(s, SFA_MEASURE_VOLUME, value)
  call check('the cube is still there: volume 1', &
       rc == SFA_OK .and. near(value, 1.0_c_double, 8 * eps))

  ! ------------------------------------------------------------ sfa_move
  do i = 1, nv
    vel(:, i) = [0.5_c_double, -0.25_c_double, 1.0_c_double]
  end do
  rc = sfa_set_velocities(s, vel)
  call check('sfa_set_velocities (rigid translation)', rc == SFA_OK, sfa_error_message(s))
  dt = 0.2_c_double
  rc = sfa_move(s, dt, dt_taken)
  ! A translation never folds a triangle, so the whole step is taken.
  call check('sfa_move: dt_taken == dt', rc == SFA_OK .and. near(dt_taken, dt, 0.0_c_double), &
       sfa_error_message(s))
  rc = sfa_get_mesh_alloc(s, xyz_out, tri_out)
  if (rc == SFA_OK) then
    call check('sfa_move: every vertex moved by dt * v', &
         max_abs_diff(xyz_out, cube_xyz + dt * vel) <= 4 * eps)
  else
    call check('sfa_move: read the mesh back', .false., sfa_error_message(s))
  end if
  rc = sfa_measure(s, SFA_MEASURE_VOLUME, value)
  call check('sfa_move: volume is still 1', rc == SFA_OK .and. near(value, 1.0_c_double, 1e-12_c_double))

  ! ------------------------------------------------------------ sfa_advect
  rc = sfa_get_mesh_alloc(s, xyz_out, tri_out)
  before = cube_xyz
  if (rc == SFA_OK) before = xyz_out
  omega = 1.0_c_double
  t0 = 0.5_c_double
  dt = 0.1_c_double
  rc = sfa_advect(s, c_funloc(rotate_z), c_loc(omega), t0, dt, dt_taken)
  call check('sfa_advect (rigid rotation): SFA_OK, dt_taken == dt', &
       rc == SFA_OK .and. near(dt_taken, dt, 0.0_c_double), sfa_error_message(s))
  call check('sfa_advect: four batched calls of all 8 vertices', ncalls == 4 .and. last_n == nv)
  call check('sfa_advect: callback times span [t, t + dt]', &
       near(tmin, t0, 4 * eps) .and. near(tmax, t0 + dt, 4 * eps))
  ! For x' = A x one classic RK4 step is x1 = (I + hA + (hA)^2/2 + (hA)^3/6 + (hA)^4/24) x0;
  ! with A a rotation generator about z this is a 2x2 [c -s; s c] in x and y.
  theta = omega * dt
  c = 1 - theta**2 / 2 + theta**4 / 24
  sn = theta - theta**3 / 6
  expected(1, :) = c * before(1, :) - sn * before(2, :)
  expected(2, :) = sn * before(1, :) + c * before(2, :)
  expected(3, :) = before(3, :)
  rc = sfa_get_mesh_alloc(s, xyz_out, tri_out)
  if (rc == SFA_OK) then
    call check('sfa_advect: positions are the RK4 step of the rotation', &
         max_abs_diff(xyz_out, expected) <= 1e-13_c_double)
  else
    call check('sfa_advect: read the mesh back', .false., sfa_error_message(s))
  end if
  rc = sfa_measure(s, SFA_MEASURE_AREA, value)
  call check('sfa_advect: area is still 6', rc == SFA_OK .and. near(value, 6.0_c_double, 1e-6_c_double))

  ! ------------------------------------------------------------ fields
  do i = 1, nv
    field(:, i) = [real(i, c_double), -0.5_c_double * i]
  end do
  rc = sfa_add_field(s, 2_c_int32_t, field, field_id)
  call check('sfa_add_field(ncomp 2): first field id is 0', rc == SFA_OK .and. field_id == 0, &
       sfa_error_message(s))
  rc = sfa_get_field_alloc(s, field_id, 2_c_int32_t, field_out)
  if (rc == SFA_OK) then
    call check('sfa_get_field_alloc gives the field back, shape (2,8)', &
         all(shape(field_out) == [2, 8]) .and. max_abs_diff(field_out, field) <= 0)
  else
    call check('sfa_get_field_alloc', .false., sfa_error_message(s))
  end if
  rc = sfa_get_field(s, field_id, 2 * nv - 1, field)
  call check('sfa_get_field with a too small capacity gives SFA_ERR_ARGUMENT', &
       rc == SFA_ERR_ARGUMENT)
  rc = sfa_get_field_alloc(s, field_id + 1, 2_c_int32_t, field_out)
  call check('an unknown field id gives SFA_ERR_ARGUMENT', rc == SFA_ERR_ARGUMENT)
  ! The host replaces the values (as after a step of its own) and reads the new ones back.
  field = 2 * field
  rc = sfa_set_field(s, field_id, nv, field)
  call check('sfa_set_field', rc == SFA_OK, sfa_error_message(s))
  rc = sfa_get_field_alloc(s, field_id, 2_c_int32_t, field_out)
  call check('sfa_set_field replaced the values', rc == SFA_OK .and. max_abs_diff(field_out, field) <= 0)
  rc = sfa_set_field(s, field_id, nv - 1, field)
  call check('sfa_set_field for another vertex count gives SFA_ERR_ARGUMENT', rc == SFA_ERR_ARGUMENT)

  ! ------------------------------------------------------------ adaptation
  ! Smoothing a cube succeeds and moves nothing (every vertex is a corner).
  rc = sfa_get_mesh_alloc(s, xyz_out, tri_out)
  before = cube_xyz
  if (rc == SFA_OK) before = xyz_out
  rc = sfa_smooth(s, 3_c_int32_t)
  call check('sfa_smooth on a cube succeeds', rc == SFA_OK)
  rc = sfa_get_mesh_alloc(s, xyz_out, tri_out)
  if (rc == SFA_OK) then
    call check('smoothing left the cube as it was', &
         all(tri_out == cube_tri) .and. max_abs_diff(xyz_out, before) <= 0)
  else
    call check('the mesh is readable after smoothing', .false., sfa_error_message(s))
  end if

  ! ------------------------------------------------------------ feature detection
  ! The (moved and turned) cube: every one of its 8 vertices is a corner, rank 2.
  rc = sfa_get_feature_ranks_alloc(s, ranks)
  if (rc == SFA_OK) then
    call check('sfa_get_feature_ranks_alloc: 8 ranks, all corners (2)', &
         size(ranks) == nv .and. all(ranks == 2))
  else
    call check('sfa_get_feature_ranks_alloc gives SFA_OK', .false., sfa_error_message(s))
  end if
  rc = sfa_get_feature_ranks(s, nv - 1, vranks)
  call check('sfa_get_feature_ranks with a too small capacity gives SFA_ERR_ARGUMENT', &
       rc == SFA_ERR_ARGUMENT)

  ! ------------------------------------------------------------ adaptation
  ! At the edge length 0.25 set above, sfa_adapt refines the unit cube: more vertices, read
  ! back with the new counts, the same volume, and still exactly 8 corners.
  rc = sfa_measure(s, SFA_MEASURE_VOLUME, volume_before)
  rc = sfa_adapt(s)
  call check('sfa_adapt refines the cube', rc == SFA_OK, sfa_error_message(s))
  rc = sfa_get_mesh_alloc(s, xyz_out, tri_out)
  if (rc == SFA_OK) then
    call check('the adapted mesh reads back with more vertices and triangles', &
         size(xyz_out, 2) > nv .and. size(tri_out, 2) > nt .and. &
         minval(tri_out) >= 1 .and. maxval(tri_out) <= size(xyz_out, 2))
  else
    call check('sfa_get_mesh_alloc after sfa_adapt', .false., sfa_error_message(s))
  end if
  rc = sfa_measure(s, SFA_MEASURE_VOLUME, value)
  call check('sfa_adapt kept the volume', rc == SFA_OK .and. near(value, volume_before, 1e-9_c_double))
  rc = sfa_get_feature_ranks_alloc(s, ranks)
  call check('the adapted cube has 8 corners', rc == SFA_OK .and. count(ranks == 2) == 8)

  ! ------------------------------------------------------------ host control
  ! A stale array (made for the 8 vertices before sfa_adapt) is refused by the checked
  ! variants; a size field coarsens the refined cube while a fixed vertex and a required
  ! edge (1-based numbering) stay exactly where they are.
  allocate(stale(3, nv))
  stale = 0
  rc = sfa_set_velocities_checked(s, nv, stale)
  call check('sfa_set_velocities_checked refuses a stale array', rc == SFA_ERR_ARGUMENT, sfa_error_message(s))
  rc = sfa_get_mesh_alloc(s, xyz_out, tri_out)
  nverts = size(xyz_out, 2)
  allocate(sizes(nverts))
  sizes = 0.6_c_double
  rc = sfa_set_size_field_checked(s, nverts, sizes)
  call check('sfa_set_size_field_checked', rc == SFA_OK, sfa_error_message(s))
  sizes(3) = -1
  rc = sfa_set_size_field(s, sizes)
  msg = sfa_error_message(s)
  call check('sfa_set_size_field refuses a negative size, naming vertex 3', &
       rc == SFA_ERR_ARGUMENT .and. index(msg, 'vertex 3 ') > 0, msg)
  fixed(1) = tri_out(1, 5)
  fixed_at = xyz_out(:, fixed(1))
  pinned(:, 1) = tri_out(1:2, 9)
  rc = sfa_set_fixed_vertices(s, 1, fixed, 1)
  call check('sfa_set_fixed_vertices', rc == SFA_OK, sfa_error_message(s))
  rc = sfa_set_required_edges(s, 1, pinned, 1)
  call check('sfa_set_required_edges', rc == SFA_OK, sfa_error_message(s))
  rc = sfa_adapt(s)
  call check('sfa_adapt with a size field and constraints', rc == SFA_OK, sfa_error_message(s))
  rc = sfa_get_mesh_alloc(s, xyz_out, tri_out)
  call check('the size field coarsened the cube, the fixed vertex in place', rc == SFA_OK .and. &
       size(xyz_out, 2) < nverts .and. &
       minval(maxval(abs(xyz_out - spread(fixed_at, 2, size(xyz_out, 2))), dim=1)) <= 0)
  rc = sfa_clear_size_field(s)
  call check('sfa_clear_size_field', rc == SFA_OK, sfa_error_message(s))
  ! Where each vertex came from: a triangle of the mesh before that sfa_adapt (1-based),
  ! and barycentric coordinates adding up to 1.
  allocate(origin_tri(size(xyz_out, 2)), origin_w(3, size(xyz_out, 2)))
  rc = sfa_get_vertex_origins(s, size(xyz_out, 2), origin_tri, origin_w, 1)
  call check('sfa_get_vertex_origins', rc == SFA_OK .and. minval(origin_tri) >= 1 .and. &
       maxval(abs(sum(origin_w, dim=1) - 1)) < 1e-14_c_double, sfa_error_message(s))
  ! A face field of one density per triangle comes back as it was set (no call since).
  allocate(densities(size(tri_out, 2)))
  densities = 0.5_c_double
  rc = sfa_add_face_field_checked(s, size(tri_out, 2), 1, densities, field_id)
  call check('sfa_add_face_field_checked', rc == SFA_OK .and. field_id == 0, sfa_error_message(s))
  densities = 0
  rc = sfa_get_face_field(s, field_id, size(densities), densities)
  call check('sfa_get_face_field', rc == SFA_OK .and. minval(densities) >= 0.5_c_double &
       .and. maxval(densities) <= 0.5_c_double, sfa_error_message(s))
  ! The host replaces the densities (after a step of its own), and reads the new ones back.
  densities = 2.5_c_double
  rc = sfa_set_face_field(s, field_id, size(tri_out, 2), densities)
  call check('sfa_set_face_field', rc == SFA_OK, sfa_error_message(s))
  densities = 0
  rc = sfa_get_face_field(s, field_id, size(densities), densities)
  call check('sfa_set_face_field replaced the densities', rc == SFA_OK .and. &
       minval(densities) >= 2.5_c_double .and. maxval(densities) <= 2.5_c_double, sfa_error_message(s))

  call sfa_destroy(s)
  s = c_null_ptr
  call finish()

contains

  subroutine finish()
    write(*, '(a,i0,a,i0,a)') 'fortran: ', npass, ' passed, ', nfail, ' failed'
    if (nfail > 0) error stop 1
    stop
  end subroutine finish

end program test_surfadapt
