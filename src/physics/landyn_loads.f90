!> Interface loads for the structures team: the loads each gear puts on the body at its hard points
!! (the upper joints a, b, c of its primary, left and right secondary struts) and the footpad load
!! at the primary's lower ball joint d, as one load vector per gear and instant, and the peak-load
!! table (per joint and component, the largest load over every accepted step with the loads of all
!! joints of that gear at the same instant).
!!
!! A gear's load vector (n_load = 21 values, lander axes): forces of a, b, c on the body [N]
!! (1:9), force of the footpad on the primary at d [N] (10:12), moments of a, b, c on the body [N m]
!! (13:21). The gear-level physics is the gear type's (gear_eval_t%f_joint, m_joint): for any gear
!! type a, b, c are the upper joints of its struts 1 to max_struts (zero for a gear with fewer) and
!! d its footpad.
module landyn_loads
  use landyn_kinds, only: wp, max_struts
  use landyn_gear_base, only: gear_eval_t
  implicit none
  private

  public :: n_load, n_joint, n_quantity, load_peaks_t, gear_load_vector, load_peaks_init, load_peaks_update
  public :: joint_names, quantity_names, load_names

  integer, parameter :: n_joint = max_struts + 1  !! joints of the peak table: a, b, c, d [-]
  integer, parameter :: n_load = 3*n_joint + 3*max_struts  !! values of a gear's load vector (21) [-]
  integer, parameter :: n_quantity = 4     !! quantities of the peak table: x, y, z, magnitude [-]
  character(len=1), parameter :: joint_names(n_joint) = ['a', 'b', 'c', 'd']  !! the hard points of the peak table [-]
  !> The quantities of the peak table.
  character(len=9), parameter :: quantity_names(n_quantity) = [character(len=9) :: 'x', 'y', 'z', 'magnitude']
  !> Names of the load vector's values (the columns of the simultaneous loads).
  character(len=4), parameter :: load_names(n_load) = [character(len=4) :: &
    'Fa_x', 'Fa_y', 'Fa_z', 'Fb_x', 'Fb_y', 'Fb_z', 'Fc_x', 'Fc_y', 'Fc_z', 'Fd_x', 'Fd_y', 'Fd_z', &
    'Ma_x', 'Ma_y', 'Ma_z', 'Mb_x', 'Mb_y', 'Mb_z', 'Mc_x', 'Mc_y', 'Mc_z']

  !> Peak-load table of all gears.
  type :: load_peaks_t
    real(wp), allocatable :: value(:, :, :)          !! (n_quantity, n_joint, n_gears) peak, signed for
                                                     !! components, >= 0 for the magnitude [N]
    real(wp), allocatable :: time(:, :, :)           !! (n_quantity, n_joint, n_gears) its instant [s]
    real(wp), allocatable :: simultaneous(:, :, :, :)  !! (n_load, n_quantity, n_joint, n_gears) the gear's
                                                       !! load vector at that instant [N, N m]
  end type load_peaks_t

contains

  !> A gear's load vector in lander axes from its evaluation (gear frame) and the gear-to-lander
  !! rotation.
  pure function gear_load_vector(rot, ge) result(v)
    real(wp), intent(in) :: rot(3, 3)          !! gear frame -> lander frame [-]
    type(gear_eval_t), intent(in) :: ge        !! the gear's evaluation
    real(wp) :: v(n_load)                      !! [N, N m]
    integer :: j
    do j = 1, n_joint
      v(3*j - 2:3*j) = matmul(rot, ge%f_joint(:, j))
    end do
    do j = 1, max_struts
      v(3*n_joint + 3*j - 2:3*n_joint + 3*j) = matmul(rot, ge%m_joint(:, j))
    end do
  end function gear_load_vector

  !> An empty table for ng gears.
  pure subroutine load_peaks_init(p, ng)
    type(load_peaks_t), intent(out) :: p       !! table
    integer, intent(in) :: ng                  !! number of gears [-]
    allocate (p%value(n_quantity, n_joint, ng), p%time(n_quantity, n_joint, ng), &
              p%simultaneous(n_load, n_quantity, n_joint, ng))
    p%value = 0.0_wp
    p%time = 0.0_wp
    p%simultaneous = 0.0_wp
  end subroutine load_peaks_init

  !> Takes the load vectors of all gears at time t into the table.
  pure subroutine load_peaks_update(p, t, v, ng)
    type(load_peaks_t), intent(inout) :: p     !! table
    real(wp), intent(in) :: t                  !! time [s]
    real(wp), intent(in) :: v(:, :)            !! (n_load, >= ng) load vectors [N, N m]
    integer, intent(in) :: ng                  !! number of gears [-]
    integer :: i, j, k
    real(wp) :: x
    do i = 1, ng
      do j = 1, n_joint
        do k = 1, n_quantity
          if (k <= 3) then
            x = v(3*(j - 1) + k, i)
          else
            x = norm2(v(3*j - 2:3*j, i))
          end if
          if (abs(x) > abs(p%value(k, j, i))) then
            p%value(k, j, i) = x
            p%time(k, j, i) = t
            p%simultaneous(:, k, j, i) = v(:, i)
          end if
        end do
      end do
    end do
  end subroutine load_peaks_update

end module landyn_loads
