! SPDX-License-Identifier: BSD-3-Clause
! An example Fortran host: a solver that knows its interface velocities itself (here the
! vortex flow of the paper's §5.2.1, time-modulated with period T = 2) and drives the
! library with sfa_move, following the schedule of the README ("Dynamic surfaces"):
! move (sub-stepping while the fold control cuts the step), smooth, and adapt every 4
! steps. Its own mesh is a latitude-longitude sphere in 1-based (3,n) arrays.
!
! Usage: vortex_host [STEPS]   (default 200 = one period with dt = 0.01)
! Prints a line every 20 steps and exits with status 1 if a call fails, the volume moves
! by more than 1 %, or the surface folds.
program vortex_host
  use, intrinsic :: iso_c_binding
  use surfadapt
  implicit none

  real(c_double), parameter :: pi = 3.14159265358979323846_c_double
  real(c_double), parameter :: period = 2, dt = 0.01_c_double, radius = 0.15_c_double
  real(c_double), parameter :: centre(3) = [0.5_c_double, 0.75_c_double, 0.5_c_double]
  integer, parameter :: nlat = 24, nlon = 48, adapt_every = 4
  type(c_ptr) :: s
  real(c_double), allocatable :: xyz(:, :), vel(:, :), midpoint(:, :)
  integer(c_int32_t), allocatable :: tris(:, :)
  real(c_double) :: t, remaining, taken, volume0, volume, turn
  integer :: steps, step
  character(len=32) :: arg

  steps = 200
  if (command_argument_count() >= 1) then
    call get_command_argument(1, arg)
    read(arg, *) steps
  end if

  call latitude_longitude_sphere(xyz, tris)
  call require(sfa_create(s), 'sfa_create')
  call require(sfa_set_mesh(s, int(size(xyz, 2), c_int32_t), xyz, int(size(tris, 2), c_int32_t), tris, 1_c_int32_t), &
               'sfa_set_mesh')
  call require(sfa_measure(s, SFA_MEASURE_VOLUME, volume0), 'sfa_measure')
  ! Adapted every few steps: one pass per sfa_adapt call is enough.
  call require(sfa_set_param(s, SFA_PARAM_ADAPT_PASSES, 1.0_c_double), 'sfa_set_param')
  write(*, '(a, i0, a)') 'vortex host: a sphere of ', size(xyz, 2), ' vertices, T = 2, dt = 0.01, sfa_move'
  write(*, '(a5, a8, a10, a14, a12)') 'step', 't', 'vertices', 'volume err %', 'max turn'

  t = 0
  do step = 1, steps
    ! One step of the host: the midpoint rule (second order; a plain Euler step would
    ! spiral outwards and gain 0.3 % of volume per step in this flow) gives each vertex
    ! its velocity for the step; sfa_move takes it, cut short where a triangle would
    ! fold, and the host repeats until the whole dt is taken.
    remaining = dt
    do while (remaining > 1e-12_c_double * dt)
      call require(sfa_get_mesh_alloc(s, xyz, tris), 'sfa_get_mesh_alloc')
      call vortex_velocity(xyz, t, vel)
      midpoint = xyz + 0.5_c_double * remaining * vel
      call vortex_velocity(midpoint, t + 0.5_c_double * remaining, vel)
      call require(sfa_set_velocities_checked(s, int(size(vel, 2), c_int32_t), vel), 'sfa_set_velocities_checked')
      call require(sfa_move(s, remaining, taken), 'sfa_move')
      t = t + taken
      remaining = remaining - taken
    end do
    ! sfa_adapt smooths too: a step is either adapted or smoothed.
    if (mod(step, adapt_every) == 0) then
      call require(sfa_adapt(s), 'sfa_adapt')
    else
      call require(sfa_smooth(s, 1_c_int32_t), 'sfa_smooth')
    end if

    call require(sfa_measure(s, SFA_MEASURE_VOLUME, volume), 'sfa_measure')
    call require(sfa_measure(s, SFA_MEASURE_MAX_NORMAL_TURN, turn), 'sfa_measure')
    if (mod(step, 20) == 0 .or. step == steps) then
      call require(sfa_get_mesh_alloc(s, xyz, tris), 'sfa_get_mesh_alloc')
      write(*, '(i5, f8.3, i10, f14.5, f12.2)') step, t, size(xyz, 2), 100 * (volume - volume0) / volume0, turn
    end if
    if (abs(volume - volume0) > 0.01_c_double * volume0 .or. turn > 150) then
      write(*, '(a, i0, a, es10.2, a, f7.2)') 'vortex host: FAILED at step ', step, ': volume change ', &
           (volume - volume0) / volume0, ', largest normal turn ', turn
      stop 1
    end if
  end do
  call sfa_destroy(s)
  write(*, '(a)') 'vortex-host: 1 passed, 0 failed'

contains

  subroutine require(status, what)
    integer(c_int), intent(in) :: status
    character(len=*), intent(in) :: what
    if (status /= SFA_OK) then
      write(*, '(a)') 'vortex host: ' // what // ': ' // sfa_error_message(s)
      stop 1
    end if
  end subroutine require

  ! The velocity of eqs. 13-15 times cos(pi t / T) at every vertex.
  subroutine vortex_velocity(p, time, v)
    real(c_double), intent(in) :: p(:, :), time
    real(c_double), allocatable, intent(out) :: v(:, :)
    real(c_double) :: m
    integer :: i
    allocate(v(3, size(p, 2)))
    m = cos(pi * time / period)
    do i = 1, size(p, 2)
      v(1, i) = m * sin(pi * p(1, i))**2 * (sin(2 * pi * p(3, i)) - sin(2 * pi * p(2, i)))
      v(2, i) = m * sin(pi * p(2, i))**2 * (sin(2 * pi * p(1, i)) - sin(2 * pi * p(3, i)))
      v(3, i) = m * sin(pi * p(3, i))**2 * (sin(2 * pi * p(2, i)) - sin(2 * pi * p(1, i)))
    end do
  end subroutine vortex_velocity

  ! Poles 1 and 2, then nlat - 1 rings of nlon vertices; triangles counter-clockwise seen
  ! from outside (1-based).
  subroutine latitude_longitude_sphere(p, tri)
    real(c_double), allocatable, intent(out) :: p(:, :)
    integer(c_int32_t), allocatable, intent(out) :: tri(:, :)
    integer :: i, j, k, a, b, c, d
    real(c_double) :: theta, phi
    allocate(p(3, 2 + (nlat - 1) * nlon), tri(3, 2 * nlon * (nlat - 1)))
    p(:, 1) = centre + [0.0_c_double, 0.0_c_double, radius]
    p(:, 2) = centre - [0.0_c_double, 0.0_c_double, radius]
    do j = 1, nlat - 1
      theta = pi * j / nlat
      do i = 0, nlon - 1
        phi = 2 * pi * i / nlon
        p(:, ring(j, i)) = centre + radius * [sin(theta) * cos(phi), sin(theta) * sin(phi), cos(theta)]
      end do
    end do
    k = 0
    do i = 0, nlon - 1
      k = k + 1
      tri(:, k) = [1, ring(1, i), ring(1, i + 1)]
      k = k + 1
      tri(:, k) = [2, ring(nlat - 1, i + 1), ring(nlat - 1, i)]
    end do
    do j = 1, nlat - 2
      do i = 0, nlon - 1
        a = ring(j, i)
        b = ring(j + 1, i)
        c = ring(j + 1, i + 1)
        d = ring(j, i + 1)
        k = k + 1
        tri(:, k) = [a, b, c]
        k = k + 1
        tri(:, k) = [a, c, d]
      end do
    end do
  end subroutine latitude_longitude_sphere

  ! Vertex i (taken modulo nlon) of ring j, counted from the north pole.
  integer function ring(j, i)
    integer, intent(in) :: j, i
    ring = 2 + (j - 1) * nlon + modulo(i, nlon) + 1
  end function ring
end program vortex_host
