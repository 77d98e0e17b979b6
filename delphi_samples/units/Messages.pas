{ Messages.pas -- headless stand-in for Delphi's Messages unit: the
  WM_PAINT message record, so that a form can paint in a
  `procedure WMPaint(var Msg: TWMPaint); message WM_PAINT;` handler, as
  Krasnov's programs do (the Forms stand-in dispatches WM_PAINT to it). }
unit Messages;

{$mode delphi}

interface

uses Windows;

const
  WM_PAINT = $000F;

type
  TMessage = record
    Msg: Cardinal;
    WParam: PtrInt;
    LParam: PtrInt;
    Result: PtrInt;
  end;
  TWMPaint = record
    Msg: Cardinal;
    DC: HDC;
    Unused: PtrInt;
    Result: PtrInt;
  end;

implementation

end.
