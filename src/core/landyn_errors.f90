!> The error collector: a growing list of messages, so that input checks report every problem,
!! not only the first. Used by the input reader, its validation and the law factories.
module landyn_errors
  implicit none
  private

  public :: input_errors_t

  !> One message (deferred length, so nothing is truncated).
  type :: message_t
    character(len=:), allocatable :: text  !! the message [-]
  end type message_t

  !> A growing list of input error messages. Grown only while input is processed.
  type :: input_errors_t
    private
    integer :: n = 0                          !! number of messages [-]
    type(message_t), allocatable :: list(:)   !! messages 1..n [-]
  contains
    procedure :: add => errors_add            !! append a message
    procedure :: count => errors_count        !! number of messages
    procedure :: message => errors_message    !! message i
    procedure :: write => errors_write        !! write all messages, one per line, to a unit
  end type input_errors_t

contains

  !> Append one message to the error list.
  subroutine errors_add(self, text)
    class(input_errors_t), intent(inout) :: self  !! error list
    character(len=*), intent(in) :: text          !! message [-]
    type(message_t), allocatable :: tmp(:)
    if (.not. allocated(self%list)) allocate (self%list(16))
    if (self%n == size(self%list)) then
      allocate (tmp(2*self%n))
      tmp(1:self%n) = self%list
      call move_alloc(tmp, self%list)
    end if
    self%n = self%n + 1
    self%list(self%n)%text = text
  end subroutine errors_add

  !> Number of messages in the list.
  pure function errors_count(self) result(n)
    class(input_errors_t), intent(in) :: self  !! error list
    integer :: n                               !! number of messages [-]
    n = self%n
  end function errors_count

  !> Message i of the list ('' when i is out of range).
  pure function errors_message(self, i) result(text)
    class(input_errors_t), intent(in) :: self  !! error list
    integer, intent(in) :: i                   !! message index, 1..count() [-]
    character(len=:), allocatable :: text      !! the message [-]
    if (i >= 1 .and. i <= self%n) then
      text = self%list(i)%text
    else
      text = ''
    end if
  end function errors_message

  !> Write every message, one per line, to a formatted unit the caller has open.
  subroutine errors_write(self, unit)
    class(input_errors_t), intent(in) :: self  !! error list
    integer, intent(in) :: unit                !! formatted output unit [-]
    integer :: i
    do i = 1, self%n
      write (unit, '(a)') self%list(i)%text
    end do
  end subroutine errors_write
end module landyn_errors
