! SPDX-License-Identifier: BSD-3-Clause
! A Fortran host built the way a compiler other than gfortran builds one: from the module's
! installed source (PREFIX/include/surfadapt.f90), compiled with the host, not from the
! installed gfortran .mod and libsurfadapt_fortran.a.
program host
  use, intrinsic :: iso_c_binding, only: c_ptr, c_double, c_int32_t
  use surfadapt
  implicit none
  type(c_ptr) :: s
  ! Unit right tetrahedron, 1-based, outward counter-clockwise triangles: volume 1/6.
  real(c_double) :: xyz(3, 4) = reshape([0d0, 0d0, 0d0, 1d0, 0d0, 0d0, 0d0, 1d0, 0d0, 0d0, 0d0, 1d0], [3, 4])
  integer(c_int32_t) :: tri(3, 4) = reshape([1, 3, 2, 1, 2, 4, 1, 4, 3, 2, 3, 4], [3, 4])
  real(c_double) :: volume
  integer :: rc

  rc = sfa_create(s)
  if (rc == SFA_OK) rc = sfa_set_mesh(s, 4, xyz, 4, tri, 1)
  if (rc == SFA_OK) rc = sfa_measure(s, SFA_MEASURE_VOLUME, volume)
  if (rc /= SFA_OK) then
    print '(a, i0, 2a)', 'status ', rc, ': ', sfa_error_message(s)
    call sfa_destroy(s)
    error stop 1
  end if
  call sfa_destroy(s)
  if (abs(volume - 1d0 / 6d0) > 1d-15) then
    print '(a, es24.17)', 'volume ', volume
    error stop 1
  end if
  print '(3a, es24.17)', 'surfadapt ', sfa_version(), ' from the module source: tetrahedron volume ', volume
end program host
